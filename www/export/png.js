// PNG of the view: rendered and read back in the same task (the drawing buffer is not preserved).
/**
 * @param {import('../viewer.js').Viewer} viewer
 * @returns {Promise<Blob>}
 */
export function png(viewer) {
  return new Promise((resolve, reject) => {
    viewer.render();
    viewer.canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be captured'))), 'image/png');
  });
}
