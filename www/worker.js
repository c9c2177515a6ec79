// Heavy refinements off the main thread: a module worker with its own wasm instance.
// First message: { init: wasm source } (a URL, or the bytes in the one-file build).
// Then { id, segments: Float64Array, options, draw } (RuledSurface.subdivide options, steps
// included; `draw`: most rulings to send back). Messages out: { id, progress } after each
// step, then { id, segments: Float32Array, rulings, drawn } (transferred; see refine.js), or
// { id, error, code, details }. A job with `kind: 'post'` is a tool path refined and posted as
// G-code (post-job.js): { id, kind, poses, tool, refine, post, draw, cam } in, its result out;
// `cam` is where the CAM module comes from (its URL or bytes), which this worker starts at its
// first such job. A job with `kind: 'optimise'` is tool poses optimised against a target and
// posted (optimise-job.js): { id, kind, poses, tool, target, post, cam } in, its result out.
import init from '../pkg/ruledlab.js';
import { setCamSource, startCam } from './cam.js';
import { refineSteps } from './refine.js';
import { postSteps } from './post-job.js';
import { optimiseSteps } from './optimise-job.js';

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
    if (data.kind === 'post' || data.kind === 'optimise') {
      if (data.cam) setCamSource(data.cam);
      await startCam();
    }
    const report = (/** @type {number} */ progress) => self.postMessage({ id, progress });
    const done =
      data.kind === 'optimise'
        ? await optimiseSteps(data, report)
        : data.kind === 'post'
          ? await postSteps(data, report)
          : await refineSteps(data, report);
    self.postMessage({ id, ...done }, { transfer: [done.segments.buffer] });
  } catch (e) {
    const error = /** @type {any} */ (e);
    self.postMessage({ id, error: String(error?.message ?? error), code: error?.code, details: error?.details });
  }
};
