// The virtual module that scripts/onefile.mjs's esbuild plugin provides.
declare module 'ruledlab:inline' {
  /** The wasm module, base64. */
  export const WASM: string;
  /** The worker's bundled source text (a classic script). */
  export const WORKER: string;
}
