// The inlined wasm (base64) and worker (source text), and the page's shell (its body before any
// script, page/shell.js), from the build's virtual module.
import { WASM, WORKER, SHELL } from 'ruledlab:inline';

export { SHELL };

/** The wasm module's bytes (decoded natively where the browser can: a millisecond, not twenty). */
export function wasmBytes() {
  const native = /** @type {{fromBase64?: (text: string) => Uint8Array}} */ (/** @type {unknown} */ (Uint8Array));
  if (typeof native.fromBase64 === 'function') return native.fromBase64(WASM);
  const text = atob(WASM);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  return bytes;
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
