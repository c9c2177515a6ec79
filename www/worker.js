// Heavy refinements off the main thread: a module worker with its own wasm instance.
// First message: { init: wasm source } (a URL, or the bytes in the one-file build).
// Then { id, segments: Float64Array, options, draw } (RuledSurface.subdivide options, steps
// included; `draw`: most rulings to send back). Messages out: { id, progress } after each
// step, then { id, segments: Float32Array, rulings, drawn } (transferred; see refine.js), or
// { id, error, code, details }.
import init from '../pkg/ruledlab.js';
import { refineSteps } from './refine.js';

/** @type {Promise<unknown> | null} */
let ready = null;

self.onmessage = async ({ data }) => {
  if ('init' in data) {
    ready = init({ module_or_path: data.init });
    return;
  }
  const { id } = data;
  try {
    await ready;
    const done = await refineSteps(data, (progress) => self.postMessage({ id, progress }));
    self.postMessage({ id, ...done }, { transfer: [done.segments.buffer] });
  } catch (e) {
    const error = /** @type {any} */ (e);
    self.postMessage({ id, error: String(error?.message ?? error), code: error?.code, details: error?.details });
  }
};
