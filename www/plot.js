// A small log-log plot in SVG (no dependencies): series of (x, y) with decade ticks and
// reference slopes, for convergence orders.

const COLORS = ['#d6292b', '#1f5fae', '#e08a1e', '#168a52', '#6b4fa8', '#444'];

/**
 * @param {{x: number[], series: {name: string, y: number[]}[], slopes?: number[], width?: number, height?: number, xLabel?: string, yLabel?: string}} spec
 * @returns {string} SVG markup
 */
export function logLogPlot({ x, series, slopes = [], width = 340, height = 250, xLabel = 'H', yLabel = 'error' }) {
  const pad = { l: 46, r: 10, t: 10, b: 36 };
  const finite = (v) => Number.isFinite(v) && v > 0;
  const ys = series.flatMap((s) => s.y.filter(finite));
  const xs = x.filter(finite);
  if (!ys.length || !xs.length) return '<svg></svg>';
  const [x0, x1] = [Math.floor(Math.log10(Math.min(...xs))), Math.ceil(Math.log10(Math.max(...xs)))];
  const [y0, y1] = [Math.floor(Math.log10(Math.min(...ys))), Math.ceil(Math.log10(Math.max(...ys)))];
  const px = (v) => pad.l + ((Math.log10(v) - x0) / Math.max(x1 - x0, 1)) * (width - pad.l - pad.r);
  const py = (v) => height - pad.b - ((Math.log10(v) - y0) / Math.max(y1 - y0, 1)) * (height - pad.t - pad.b);
  const parts = [];
  for (let e = x0; e <= x1; e++) {
    parts.push(`<line x1="${px(10 ** e)}" x2="${px(10 ** e)}" y1="${pad.t}" y2="${height - pad.b}" class="grid"/>`);
    parts.push(`<text x="${px(10 ** e)}" y="${height - pad.b + 14}" text-anchor="middle">10<tspan dy="-5" font-size="8">${e}</tspan></text>`);
  }
  for (let e = y0; e <= y1; e += Math.max(1, Math.ceil((y1 - y0) / 6))) {
    parts.push(`<line x1="${pad.l}" x2="${width - pad.r}" y1="${py(10 ** e)}" y2="${py(10 ** e)}" class="grid"/>`);
    parts.push(`<text x="${pad.l - 4}" y="${py(10 ** e) + 4}" text-anchor="end">10<tspan dy="-5" font-size="8">${e}</tspan></text>`);
  }
  // reference slopes through the first point of the first series
  const anchor = series[0].y.findIndex(finite);
  for (const [k, p] of slopes.entries()) {
    if (anchor < 0) break;
    const xa = x[anchor], ya = series[0].y[anchor] * 2;
    const xb = Math.min(...xs), yb = ya * (xb / xa) ** p;
    parts.push(`<line x1="${px(xa)}" y1="${py(ya)}" x2="${px(xb)}" y2="${py(Math.max(yb, 10 ** y0))}" class="slope"/>`);
    parts.push(`<text x="${px(xb) + 4}" y="${py(Math.max(yb, 10 ** y0)) - 4 - 10 * k}" class="slope-label">slope ${p}</text>`);
  }
  series.forEach((s, k) => {
    const pts = x.map((xv, i) => [xv, s.y[i]]).filter(([, yv]) => finite(yv));
    const color = COLORS[k % COLORS.length];
    parts.push(`<polyline fill="none" stroke="${color}" stroke-width="2" points="${pts.map(([a, b]) => `${px(a)},${py(b)}`).join(' ')}"/>`);
    for (const [a, b] of pts) parts.push(`<circle cx="${px(a)}" cy="${py(b)}" r="2.5" fill="${color}"/>`);
    parts.push(`<text x="${pad.l + 8}" y="${pad.t + 12 + 13 * k}" fill="${color}">${s.name}</text>`);
  });
  parts.push(`<text x="${(width + pad.l) / 2}" y="${height - 4}" text-anchor="middle">${xLabel}</text>`);
  parts.push(`<text x="12" y="${(height - pad.b) / 2}" transform="rotate(-90 12 ${(height - pad.b) / 2})" text-anchor="middle">${yLabel}</text>`);
  return `<svg class="plot" viewBox="0 0 ${width} ${height}" width="100%" role="img" aria-label="log-log plot of ${yLabel} against ${xLabel}">${parts.join('')}</svg>`;
}
