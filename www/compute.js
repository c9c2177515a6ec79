// Runs refinements in the worker (www/worker.js), one job at a time; a newer job supersedes
// an older one, whose result is dropped.
let worker = null;
let nextId = 0;
const jobs = new Map();

/**
 * Refines `segments` with `options` in the worker.
 * @param {Float64Array} segments 6 numbers per ruling
 * @param {object} options RuledSurface.subdivide options
 * @param {(fraction: number) => void} onProgress
 * @returns {Promise<{segments: Float32Array, rulings: number}>}
 */
export function refineInWorker(segments, options, onProgress = () => {}) {
  worker ??= new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  worker.onmessage = ({ data }) => {
    const job = jobs.get(data.id);
    if (!job) return;
    if ('progress' in data) job.onProgress(data.progress);
    else {
      jobs.delete(data.id);
      if (data.error) job.reject(new Error(data.error));
      else job.resolve(data);
    }
  };
  const id = ++nextId;
  for (const [old, job] of jobs) {
    jobs.delete(old);
    job.reject(Object.assign(new Error('superseded'), { superseded: true }));
  }
  return new Promise((resolve, reject) => {
    jobs.set(id, { resolve, reject, onProgress });
    worker.postMessage({ id, segments, options });
  });
}
