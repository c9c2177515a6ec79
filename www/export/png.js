// PNG of the view, at 1×, 2× or 4× of its size, with the labels and the legend drawn in.
import { parseRich } from '../ui/richtext.js';
import { STYLES } from '../theme.js';
import { legendOf } from '../scene.js';
import { greatest } from '../reduce.js';

/**
 * @param {import('../stage.js').Stage} stage
 * @param {{scale?: number, legend?: boolean}} [options]
 * @returns {Promise<Blob>}
 */
export async function png(stage, { scale = 1, legend = true } = {}) {
  const { viewer } = stage;
  const { canvas } = viewer;
  const [w, h] = [canvas.clientWidth, canvas.clientHeight];
  const out = document.createElement('canvas');
  [out.width, out.height] = [Math.round(w * scale), Math.round(h * scale)];
  const ctx = /** @type {CanvasRenderingContext2D} */ (out.getContext('2d'));
  viewer.render({ scale, full: true });
  ctx.drawImage(canvas, 0, 0, out.width, out.height);
  viewer.render();
  ctx.scale(scale, scale);
  ctx.fillStyle = '#1d2435';
  // labels where the view placed them
  [...viewer.labelLayer.children].forEach((el, k) => {
    const label = viewer.built?.labels?.[k];
    const match = /translate\(([-\d.e]+)px, ([-\d.e]+)px\)/.exec(/** @type {HTMLElement} */ (el).style.transform);
    if (!label || !match || /** @type {HTMLElement} */ (el).hidden) return;
    drawRich(ctx, label.text, Number(match[1]) + 3, Number(match[2]) + 13, 'italic 15px "Times New Roman", serif');
  });
  if (legend && stage.scene) {
    const entries = legendOf(stage.scene, stage.params, viewer.built);
    ctx.font = '12px system-ui, sans-serif';
    const width =
      greatest(
        entries.map((e) => ctx.measureText(stage.i18n.t(e.label)).width),
        0,
      ) + 56;
    ctx.fillStyle = 'rgba(255,255,255,0.88)';
    ctx.fillRect(10, 8, width, 8 + 18 * entries.length);
    entries.forEach((entry, k) => {
      const y = 22 + 18 * k;
      const style = STYLES[entry.style];
      ctx.strokeStyle = ctx.fillStyle = style.color;
      if (style.kind === 'line') {
        ctx.lineWidth = Math.min(Math.max(style.width, 1.2), 5);
        ctx.setLineDash(style.dash ?? []);
        ctx.beginPath();
        ctx.moveTo(18, y);
        ctx.lineTo(46, y);
        ctx.stroke();
        ctx.setLineDash([]);
      } else if (style.kind === 'point') {
        ctx.beginPath();
        ctx.arc(32, y, Math.min(style.size / 2, 5), 0, 2 * Math.PI);
        ctx.fill();
      } else ctx.fillRect(22, y - 6, 20, 12);
      ctx.fillStyle = '#1d2435';
      drawRich(ctx, stage.i18n.t(entry.label), 54, y + 4, '12px system-ui, sans-serif');
    });
  }
  return new Promise((resolve, reject) =>
    out.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be captured'))), 'image/png'),
  );
}

/** Text with R_{i,i+1}-style subscripts on a 2D canvas. */
function drawRich(
  /** @type {CanvasRenderingContext2D} */ ctx,
  /** @type {string} */ text,
  /** @type {number} */ x,
  /** @type {number} */ y,
  /** @type {string} */ font,
) {
  const size = Number(/(\d+)px/.exec(font)?.[1] ?? 12);
  for (const part of parseRich(text)) {
    ctx.font = part.kind === 'text' ? font : font.replace(`${size}px`, `${Math.round(size * 0.72)}px`);
    const dy = part.kind === 'sub' ? size * 0.28 : part.kind === 'sup' ? -size * 0.35 : 0;
    ctx.fillText(part.text, x, y + dy);
    x += ctx.measureText(part.text).width;
  }
}
