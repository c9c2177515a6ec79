// Saving a file the page made (a figure, data, a program, a one-file page) as a download.

/** Downloads `content` (a string or a Blob) as `filename`. */
export function download(/** @type {string} */ filename, /** @type {string | Blob} */ content, type = 'text/plain') {
  const blob = content instanceof Blob ? content : new Blob([content], { type });
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: filename });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
