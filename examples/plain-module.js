// The package as a plain ES module: no bundler, no framework. Every wasm object is freed in
// `finally`, and the numbers reach the page as text.
import init, { AnalyticSurface } from '../pkg/ruledlab.js';

await init();
const hyperboloid = AnalyticSurface.byName('hyperboloid');
try {
  const surface = hyperboloid.sample(24);
  try {
    const { striction, distributionMean } = surface.invariants();
    const rows = [];
    for (let i = 0; i < 6; i++) {
      const m = [...striction.subarray(3 * i, 3 * i + 3)].map((x) => x.toFixed(4)).join(', ');
      const tr = document.createElement('tr');
      for (const text of [String(i + 1), `(${m})`, distributionMean[i].toFixed(5)]) tr.insertCell().textContent = text;
      rows.push(tr);
    }
    document.querySelector('#table tbody').replaceChildren(...rows);
  } finally {
    surface.free();
  }
} finally {
  hyperboloid.free();
}
document.body.dataset.ready = '1';
