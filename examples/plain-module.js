// The package as a plain ES module: no bundler, no framework.
import init, { AnalyticSurface } from '../pkg/ruledlab.js';

await init();
const hyperboloid = AnalyticSurface.byName('hyperboloid');
const surface = hyperboloid.sample(24);
const { striction, distributionMean } = surface.invariants();
const rows = [];
for (let i = 0; i < 6; i++) {
  const m = [...striction.subarray(3 * i, 3 * i + 3)].map((x) => x.toFixed(4)).join(', ');
  const tr = document.createElement('tr');
  tr.innerHTML = `<td>${i + 1}</td><td>(${m})</td><td>${distributionMean[i].toFixed(5)}</td>`;
  rows.push(tr);
}
document.querySelector('#table tbody').replaceChildren(...rows);
document.body.dataset.ready = '1';
surface.free();
hyperboloid.free();
