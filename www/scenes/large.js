// Large models: thousands of rulings refined in a Web Worker with progress shown, the page
// staying responsive; small jobs are computed at once on the main thread.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { refineInWorker } from '../compute.js';
import { COLORS } from '../theme.js';

/** Output sizes above this go to the worker. */
const WORKER_THRESHOLD = 50_000;

export const scene = {
  id: 'large',
  title: 'Large models in a Web Worker',
  params: [
    { key: 'n', label: 'Rulings N', type: 'range', min: 100, max: 10000, step: 100, value: 10000 },
    { key: 'steps', label: 'Four-point steps', type: 'range', min: 0, max: 7, step: 1, value: 0 },
    { key: 'rulings', label: 'Draw every ruling', type: 'checkbox', value: false },
  ],
  text: `
<h2>Large models</h2>
<p>A helicoid of up to 10 000 rulings, refined by up to seven steps of the four-point scheme: up to
1 280 000 rulings (the library's limit is 4 194 304 per surface, refused with a clear message above). Small jobs are computed at once; anything larger runs in a Web Worker with its
own copy of the WebAssembly module, so the page keeps drawing and answering while a progress bar
fills. The geometry crosses between threads as one typed array, never as per-ruling objects.</p>`,

  create(p) {
    const helicoid = AnalyticSurface.byName('helicoid');
    const coarse = helicoid.sample(p.n, { uMin: 0, uMax: 12, closed: false });
    helicoid.free();
    const input = coarse.segments();
    const expected = (p.n - 1) * 2 ** p.steps + 1;
    const scene = (segments, rulings) => ({
      bounds: bounds(segments),
      camera: { yaw: -1.0, pitch: 0.3 },
      readout: { rulings },
      readoutLabels: { rulings: 'rulings drawn' },
      build(gl) {
        const layers = [stripMesh(gl, segments, { front: [0.45, 0.64, 0.9, 1], back: [0.98, 0.76, 0.5, 1] })];
        if (p.rulings) layers.push(new LineBatch(gl, segments, { color: COLORS.ruling, width: 0.6 }));
        return layers;
      },
    });
    if (expected <= WORKER_THRESHOLD) {
      const refined = p.steps ? coarse.subdivide({ scheme: 'four-point', steps: p.steps }) : coarse;
      const result = scene(refined.segmentsF32(), refined.length);
      if (refined !== coarse) refined.free();
      coarse.free();
      return result;
    }
    const first = scene(coarse.segmentsF32(), p.n);
    coarse.free();
    first.later = (onProgress) =>
      refineInWorker(input, { scheme: 'four-point', steps: p.steps }, onProgress).then(({ segments, rulings }) => scene(segments, rulings));
    return first;
  },

  legend: [['ruling', 'helicoid strip (rulings on request)']],
};
