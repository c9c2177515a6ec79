// Writes the printable models of the book's chapter "Paper models" (docs/src/images/paper-models/)
// with the built package (the strips and patterns are the CAM module's): a cone, the tangent surface of a helix and a strip of the hyperboloid
// (Section 3's approximate development), each as SVG at 1:1 in millimetres.
// tests/node/developable.test.mjs checks that the files are what the package makes now.
// Usage: node scripts/paper-models.mjs [--check]
import { readFileSync, writeFileSync } from 'node:fs';
import * as ruledlab from '../pkg/ruledlab.js';
import * as cam from '../pkg/cam/ruledlab_cam.js';

ruledlab.initSync({ module: readFileSync(new URL('../pkg/ruledlab_bg.wasm', import.meta.url)) });
cam.initSync({ module: readFileSync(new URL('../pkg/cam/ruledlab_cam_bg.wasm', import.meta.url)) });

/** `m` points of the helix (r cos u, r sin u, p u), u over `turns` turns. */
export function helix(/** @type {number} */ m, /** @type {number} */ turns, r = 1, p = 0.3) {
  const out = new Float64Array(3 * m);
  for (let i = 0; i < m; i++) {
    const u = (turns * 2 * Math.PI * i) / (m - 1);
    out.set([r * Math.cos(u), r * Math.sin(u), p * u], 3 * i);
  }
  return out;
}

/** The three models: file name and SVG text. @returns {Array<[string, string]>} */
export function models() {
  const { FlatPattern, coneSurface, tangentSurface } = cam;
  const { AnalyticSurface } = ruledlab;
  /** @type {Array<[string, string]>} */
  const out = [];
  // a right circular cone (radius 1, height 2) all round: a sector of angle 2π sin α, α = atan(1/2)
  const cone = coneSurface(helix(49, 1, 1, 0), [0, 0, 2], 0.2, 1);
  const conePattern = FlatPattern.unfold(cone);
  out.push(['cone.svg', conePattern.svg({ scale: 70 })]);
  // the tangent surface of a helix over one turn: its edge of regression unrolls onto a circle of
  // radius (r² + p²)/r
  const tangent = tangentSurface(helix(61, 1, 1, 0.3), 0, 1.2);
  const tangentPattern = FlatPattern.unfold(tangent);
  out.push(['helix-tangent.svg', tangentPattern.svg({ scale: 40 })]);
  // a quarter of the hyperboloid, on one side of its waist: Section 3's approximate development
  const hyperboloid = AnalyticSurface.byName('hyperboloid');
  const strip = hyperboloid.sample(25, { uMin: 0, uMax: Math.PI / 2, vMin: -1.3, vMax: -0.3 });
  const approximate = FlatPattern.approximate(strip.segments());
  out.push(['hyperboloid.svg', approximate.svg({ scale: 40 })]);
  for (const o of [conePattern, tangentPattern, hyperboloid, strip, approximate]) o.free();
  return out;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const check = process.argv.includes('--check');
  for (const [name, svg] of models()) {
    const path = new URL(`../docs/src/images/paper-models/${name}`, import.meta.url);
    if (check) {
      if (readFileSync(path, 'utf8') !== svg) throw new Error(`${name} is not what the package makes now`);
    } else writeFileSync(path, svg);
  }
}
