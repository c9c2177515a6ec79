// The CAM module (pkg/cam/ruledlab_cam.js: tool paths, their quality, five-axis machines, the
// G-code posts, tool poses and target curves read from files), started once per page when it is
// first asked for — by the milling scene (its `needs`), an import of tool poses, a program of the
// package (`ruledlab/cam`) — never before: the teaching module carries none of it. Where its wasm
// comes from is core.js's `configure({ cam })` (by default pkg/cam/ruledlab_cam_bg.wasm beside the
// package's files); the worker, which starts its own instance, is handed the same source.
import { mark } from './timing.js';

/** @typedef {typeof import('../pkg/cam/ruledlab_cam.js')} CamModule */
/** @typedef {import('./core.js').WasmSource} WasmSource */

/** @type {WasmSource | (() => WasmSource) | null} where its wasm comes from, where configured */
let given = null;

/** Where the CAM module's wasm comes from (core.js's `configure({ cam })`), before it starts. */
export function setCamSource(/** @type {WasmSource | (() => WasmSource)} */ source) {
  given = source;
}

/** The CAM module's wasm source (a function given is asked once, when the module starts). */
export function camSource() {
  if (typeof given === 'function') given = given();
  return given ?? new URL('../pkg/cam/ruledlab_cam_bg.wasm', import.meta.url).href;
}

/** @type {Promise<CamModule> | null} */
let ready = null;
/** @type {CamModule | null} */
let loaded = null;

/** Starts the CAM module (once); resolves to its exports once they can be called. */
export function startCam() {
  ready ??= import('../pkg/cam/ruledlab_cam.js').then(async (m) => {
    await m.default({ module_or_path: /** @type {any} */ (camSource()) });
    mark('ruledlab:cam-compiled');
    loaded = m;
    return m;
  });
  // (a load that failed is tried again at the next call)
  ready.catch(() => {
    ready = null;
  });
  return ready;
}

/**
 * The CAM module's exports, once started (a scene that `needs` it is opened only then); throws an
 * Error of code `not-loaded` before.
 * @returns {CamModule}
 */
export function cam() {
  if (!loaded)
    throw Object.assign(new Error('ruledlab: the CAM module is not started yet (await startCam() first)'), {
      code: 'not-loaded',
    });
  return loaded;
}

/** Whether the CAM module has been started (for the tests that read the network log). */
export function camStarted() {
  return loaded !== null;
}
