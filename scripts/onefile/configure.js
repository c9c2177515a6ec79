// Side effect, imported first by both entries: the core takes the inlined wasm and worker,
// before any view module starts it; the wasm is decoded when the core starts (not while this
// script runs: the page paints first) and compiled asynchronously by WebAssembly.instantiate.
import { configure } from '../../www/core.js';
import { useBlocks, useBody } from '../../www/page/onefile.js';
import { blocksHtml } from './blocks.js';
import { camBytes, wasmBytes, workerFactory, SHELL } from './inline.js';

configure({ wasm: wasmBytes, cam: camBytes, worker: workerFactory() });
// the page's copies of itself (Share → one file) carry the same shell
useBody(SHELL);
// … and the same data blocks (blocks.js)
useBlocks(blocksHtml());
