// Side effect, imported first by both entries: the core takes the inlined wasm and worker,
// before any view module starts it.
import { configure } from '../../www/core.js';
import { wasmBytes, workerFactory } from './inline.js';

configure({ wasm: wasmBytes(), worker: workerFactory() });
