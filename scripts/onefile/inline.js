// The inlined wasm (hex: hex.js) and worker (source text), and the page's shell (its body before
// any script, page/shell.js), from the build's virtual module.
import { WASM, WORKER, SHELL } from 'ruledlab:inline';
import { hexBytes } from './hex.js';

export { SHELL };

/** The wasm module's bytes (hex.js: decoded natively where the browser can). */
export function wasmBytes() {
  return hexBytes(WASM);
}

/**
 * Makes workers from the inlined worker source: a classic worker from a blob: URL (allowed by
 * worker-src blob:), since module workers from blob: URLs do not start in file:// pages.
 */
export function workerFactory() {
  /** @type {string | null} */
  let url = null;
  return () => {
    url ??= URL.createObjectURL(new Blob([WORKER], { type: 'text/javascript' }));
    return new Worker(url);
  };
}
