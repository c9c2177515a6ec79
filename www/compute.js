// Runs refinements in a Web Worker (www/worker.js, with its own wasm instance), one job at a
// time; a newer job supersedes an older one, whose result is dropped.
import { newWorker, wasmSource } from './core.js';

/** @type {Worker | null} */
let worker = null;
let nextId = 0;
/** @type {Map<number, {resolve: (v: any) => void, reject: (e: any) => void, onProgress: (f: number) => void}>} */
const jobs = new Map();

/**
 * Refines `segments` with `options` in the worker.
 * @param {Float64Array} segments 6 numbers per ruling
 * @param {object} options RuledSurface.subdivide options, `steps` included
 * @param {(fraction: number) => void} [onProgress]
 * @param {number} [draw]  most rulings to send back (every k-th above it)
 * @returns {Promise<{segments: Float32Array, rulings: number, drawn: number}>}
 */
export function refineInWorker(segments, options, onProgress = () => {}, draw = Infinity) {
  if (!worker) {
    worker = newWorker();
    worker.postMessage({ init: wasmSource() });
    worker.onmessage = ({ data }) => {
      const job = jobs.get(data.id);
      if (!job) return;
      if ('progress' in data) job.onProgress(data.progress);
      else {
        jobs.delete(data.id);
        if (data.error) job.reject(Object.assign(new Error(data.error), { code: data.code }));
        else job.resolve(data);
      }
    };
  }
  const id = ++nextId;
  for (const [old, job] of jobs) {
    jobs.delete(old);
    job.reject(Object.assign(new Error('superseded'), { superseded: true }));
  }
  return new Promise((resolve, reject) => {
    jobs.set(id, { resolve, reject, onProgress });
    /** @type {Worker} */ (worker).postMessage({ id, segments, options, draw });
  });
}
