// Starts the WebAssembly core once per page, for the page, every <ruled-view> and the worker.
// By default the module is fetched from ../pkg/ruledlab_bg.wasm relative to this file, so an
// installed package needs no configuration; `configure({ wasm })` takes a URL, a Response,
// bytes or a compiled WebAssembly.Module instead, or a function returning one, called when the
// core starts (the one-file build decodes its inlined bytes only then). The CAM module
// (pkg/cam/: tool paths, machines, G-code) is a second one, started only when asked for
// (cam.js); `configure({ cam })` says where it comes from, the same ways.
import init from '../pkg/ruledlab.js';
import { mark } from './timing.js';
import { setCamSource } from './cam.js';

/** @typedef {string | URL | Response | BufferSource | WebAssembly.Module} WasmSource */

/** @type {WasmSource | (() => WasmSource) | null} */
let source = null;
/** @type {Promise<unknown> | null} */
let ready = null;
/** @type {{memory: WebAssembly.Memory} | null} */
let instance = null;
/** @type {(() => Worker) | null} */
let workerFactory = null;

/**
 * Where the wasm comes from (or a function that says, called once when the core starts), where
 * the CAM module's comes from (called once when it is first asked for), and how workers are made;
 * call before the first view starts.
 * @param {{wasm?: WasmSource | (() => WasmSource), cam?: WasmSource | (() => WasmSource), worker?: () => Worker}} options
 */
export function configure({ wasm, cam, worker } = {}) {
  if (ready && wasm !== undefined)
    throw new Error('ruledlab: configure({ wasm }) must come before the first view starts');
  if (wasm !== undefined) source = wasm;
  if (cam !== undefined) setCamSource(cam);
  if (worker !== undefined) workerFactory = worker;
}

/** The wasm source in use (for the worker, which starts its own instance). */
export function wasmSource() {
  if (typeof source === 'function') source = source();
  return source ?? new URL('../pkg/ruledlab_bg.wasm', import.meta.url).href;
}

/** Starts the core (once); resolves when its exports can be called. */
export function start() {
  ready ??= init({ module_or_path: /** @type {any} */ (wasmSource()) }).then((exports) => {
    mark('ruledlab:wasm-compiled');
    instance = /** @type {any} */ (exports);
    return exports;
  });
  return ready;
}

/** Bytes of wasm memory in use (it grows, never shrinks: a leak shows as growth); 0 before start. */
export function memoryBytes() {
  return instance?.memory.buffer.byteLength ?? 0;
}

/**
 * A new worker for heavy computations (www/worker.js unless configured otherwise). Written the
 * way bundlers read it — `new Worker(new URL('./worker.js', import.meta.url), { type: 'module' })`
 * — so that Vite, webpack 5 and esbuild-based builds bundle worker.js with its imports as a worker
 * entry of its own and put its URL here. A worker's script must come from the document's own
 * origin: where this module was loaded from another one (a CDN, the site of a Share snippet) or
 * the document is sandboxed (an opaque origin), a module worker made from a blob: URL of this
 * origin imports worker.js (whose server allows that, as a static CDN does). Throws where no
 * worker can be made; compute.js then works here (and says so once: `reportNoWorker`).
 */
export function newWorker() {
  if (workerFactory) return workerFactory();
  // where worker.js is unbundled, beside this module (bundlers leave this URL alone: they bundle
  // the worker from the expression below; scripts/web.mjs maps both to the site's worker file)
  const beside = new URL(/* @vite-ignore */ /* webpackIgnore: true */ './worker.js', import.meta.url);
  if (beside.origin === globalThis.origin)
    return new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  const shim = URL.createObjectURL(new Blob([`import ${JSON.stringify(beside.href)};`], { type: 'text/javascript' }));
  return new Worker(shim, { type: 'module' });
}

let warned = false;

/**
 * Says once in the console that no worker could start here and why: large refinements then run
 * on the main thread, in steps, and the page may answer slowly while they run.
 * @param {unknown} reason  the error, or the worker's error event
 */
export function reportNoWorker(reason) {
  if (warned) return;
  warned = true;
  const event = /** @type {{type?: string, message?: string}} */ (reason);
  const why = event?.type === 'error' ? event.message || 'its script did not load' : String(reason);
  console.warn(
    `ruledlab: no Web Worker could start here (${why}); large refinements run on the main thread instead, between frames, and the page may answer slowly while they run.`,
  );
}
