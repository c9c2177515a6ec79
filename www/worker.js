// The page's long jobs off the main thread: a module worker with its own wasm instance.
// First message: { init: wasm source } (a URL, or the bytes in the one-file build).
// Then { id, kind, ...job } (jobs.js: `kind` names the routine, the rest is what it takes; a CAM
// job carries `cam`, where the CAM module comes from — its URL or bytes —, which this worker
// starts at its first such job). Messages out: { id, progress } as the job goes, then
// { id, ...result } (its typed arrays transferred: compute.js), or { id, error, code, details }.
import init from '../pkg/ruledlab.js';
import { setCamSource, startCam } from './cam.js';
import { STEPS, CAM_KINDS } from './jobs.js';

/** @type {Promise<unknown> | null} */
let ready = null;

self.onmessage = async ({ data }) => {
  if ('init' in data) {
    ready = init({ module_or_path: data.init });
    return;
  }
  const { id, kind } = data;
  try {
    await ready;
    if (CAM_KINDS.has(kind)) {
      if (data.cam) setCamSource(data.cam);
      await startCam();
    }
    const report = (/** @type {number} */ progress) => self.postMessage({ id, progress });
    const done = await STEPS[/** @type {import('./jobs.js').JobKind} */ (kind)](data, report);
    // every typed array of the result moves, not copied (each buffer once)
    const buffers = new Set(Object.values(done).flatMap((v) => (ArrayBuffer.isView(v) ? [v.buffer] : [])));
    self.postMessage({ id, ...done }, { transfer: [...buffers] });
  } catch (e) {
    const error = /** @type {any} */ (e);
    self.postMessage({ id, error: String(error?.message ?? error), code: error?.code, details: error?.details });
  }
};
