// The JavaScript API's answers for test_js_parity.py: reads the inputs (JSON, argv[2]), computes
// with the built package loaded in Node as tests/node/load.mjs loads it, writes the results
// (JSON, argv[3]; NaN and ±Infinity as strings, every typed array as a plain list).
import { readFileSync, writeFileSync } from 'node:fs';
import ruledlab, { cam } from '../../tests/node/load.mjs';

const input = JSON.parse(readFileSync(process.argv[2], 'utf8'));
const { RuledSurface, LineCongruence, AnalyticSurface, AnalyticCongruence } = ruledlab;

/** @param {any} value */
const plain = (value) =>
  ArrayBuffer.isView(value) ? Array.from(/** @type {ArrayLike<number>} */ (/** @type {unknown} */ (value))) : value;
/** @param {object} object */
const arrays = (object) => Object.fromEntries(Object.entries(object).map(([k, v]) => [k, plain(v)]));

const surface = RuledSurface.fromSegments(new Float64Array(input.segments));
/** @type {Record<string, unknown>} */
const out = {
  invariants: arrays(surface.invariants()),
  invariantsClosed: arrays(surface.invariants({ closed: true })),
  fourPoint: plain(surface.subdivide({ scheme: 'four-point', steps: 2 }).segments()),
  variational: plain(surface.subdivide({ scheme: 'variational', steps: 1, n: 6 }).segments()),
  lines: plain(surface.subdivide({ scheme: 'bspline', degree: 3, steps: 1, space: 'lines' }).segments()),
  development: plain(surface.development()),
  envelopeRadii: plain(surface.envelopeRadii()),
  hingeAngles: plain(surface.hingeAngles()),
  bend: plain(surface.bend(0.4).segments()),
  complex: arrays(surface.linearComplex()),
  polygon: plain(ruledlab.subdividePolygon(new Float64Array(input.points), { scheme: 'bspline', degree: 3, steps: 2 })),
  fourPointPolygon: plain(
    ruledlab.subdividePolygon(new Float64Array(input.points), { scheme: 'four-point', steps: 1 }),
  ),
  formulas: plain(
    ruledlab.evaluateFormulas({ formulas: ['sin(a*u)', 'u^3 - b'], parameters: { a: 2, b: 0.5 } }, input.at),
  ),
  sample: plain(AnalyticSurface.byName('helical').sample(50).segments()),
  samplingErrors: AnalyticSurface.byName('hyperboloid').samplingErrors(40),
};
const grid = AnalyticCongruence.byName('example5').grid(7, 8);
const congruence = LineCongruence.fromGrid(7, 8, grid.segments());
out.butterfly = plain(congruence.subdivide({ scheme: 'butterfly', steps: 1 }).segments());
out.coupled = plain(congruence.subdivide({ scheme: 'variational', K: 4 }).segments());
out.focal = arrays(congruence.focal());
const path = cam.ToolPath.example(7).refine({ steps: 2 });
out.gcode = path.export('gcode', { machine: 'table-table-ac', dialect: 'sinumerik' });
out.post = arrays(path.post({ machine: 'head-table-bc' }));
// the deviation of the program as posted from the example's profile
const target = cam.ToolPath.exampleProfile(40);
const measured = path.post({ machine: 'head-table-bc', target });
out.deviation = measured.deviation && arrays(measured.deviation);

writeFileSync(
  process.argv[3],
  JSON.stringify(out, (_k, v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v)),
);
