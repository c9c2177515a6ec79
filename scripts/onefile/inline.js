// The inlined wasm modules (hex: hex.js) — the teaching module and the CAM module, each decoded
// only when it starts — the worker (source text), and the page's shell (its body before any
// script, page/shell.js), from the build's virtual module; in the one-file page the three big
// texts are data blocks beside the script (blocks.js).
import { WASM, CAM_WASM, WORKER, SHELL } from 'ruledlab:inline';
import { blockText } from './blocks.js';
import { hexBytes } from './hex.js';

export { SHELL };

/** The teaching module's bytes (hex.js: decoded natively where the browser can). */
export function wasmBytes() {
  return hexBytes(blockText(WASM));
}

/** The CAM module's bytes, decoded when it is first asked for (the milling scene, an import of tool poses). */
export function camBytes() {
  return hexBytes(blockText(CAM_WASM));
}

/**
 * Makes workers from the inlined worker source: a classic worker from a blob: URL (allowed by
 * worker-src blob:), since module workers from blob: URLs do not start in file:// pages.
 */
export function workerFactory() {
  /** @type {string | null} */
  let url = null;
  return () => {
    url ??= URL.createObjectURL(new Blob([blockText(WORKER)], { type: 'text/javascript' }));
    return new Worker(url);
  };
}
