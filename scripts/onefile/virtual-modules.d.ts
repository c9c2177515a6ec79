// The virtual module that scripts/onefile.mjs's esbuild plugin provides.
declare module 'ruledlab:inline' {
  /** The teaching module's wasm, hex (hex.js). */
  export const WASM: string;
  /** The CAM module's wasm, hex. */
  export const CAM_WASM: string;
  /** The worker's bundled source text (a classic script). */
  export const WORKER: string;
  /** The one-file page's body before its module: the shell and its first lines (page/shell.js). */
  export const SHELL: string;
}
