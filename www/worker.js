// Heavy refinements off the main thread: a module worker with its own wasm instance.
// Message in: { id, segments: Float64Array, options } (RuledSurface.subdivide options, steps
// included). Messages out: { id, progress } after each step (by work done, later steps being
// larger), then { id, segments: Float32Array, rulings } (transferred), or { id, error }.
import init, { RuledSurface } from '../pkg/ruledlab.js';

const ready = init({ module_or_path: new URL('../pkg/ruledlab_bg.wasm', import.meta.url) });

self.onmessage = async ({ data: { id, segments, options } }) => {
  try {
    await ready;
    let surface = RuledSurface.fromSegments(segments);
    const steps = options.steps ?? 1;
    const total = 2 ** steps - 1; // step k costs about 2^k
    for (let k = 0; k < steps; k++) {
      const next = surface.subdivide({ ...options, steps: 1 });
      surface.free();
      surface = next;
      self.postMessage({ id, progress: (2 ** (k + 1) - 1) / total });
    }
    const out = surface.segmentsF32();
    const rulings = surface.length;
    surface.free();
    self.postMessage({ id, segments: out, rulings }, [out.buffer]);
  } catch (e) {
    self.postMessage({ id, error: String(e.message ?? e) });
  }
};
