// Runs refinements in a Web Worker (www/worker.js, with its own wasm instance), one job at a
// time; a newer job supersedes an older one, whose result is dropped. Where no worker can
// start — a sandboxed frame, a page whose Content-Security-Policy forbids the worker's script —
// the same job (refine.js) runs on the main thread, yielding between steps. A tool path's post
// (post-job.js) and an optimisation of its poses (optimise-job.js) run the same way; as they can
// take a minute, a newer job or cancelWork() stops the worker computing one (a new one starts
// for the next job).
import { newWorker, reportNoWorker, wasmSource } from './core.js';
import { camSource } from './cam.js';
import { refineSteps } from './refine.js';
import { postSteps } from './post-job.js';
import { optimiseSteps } from './optimise-job.js';

/** @type {Worker | null} */
let worker = null;
/** Whether workers cannot start here (then every job runs on the main thread). */
let noWorker = false;
let nextId = 0;
/**
 * @typedef {{resolve: (v: any) => void, reject: (e: any) => void, onProgress: (f: number) => void, job: any, post?: boolean, optimise?: boolean}} Job
 *   job: a refinement's {segments, options, draw}, a post's (post-job.js) or an optimisation's
 *   (optimise-job.js)
 */
/** @type {Map<number, Job>} */
const jobs = new Map();

/** The error of a job that a newer one replaced. */
const superseded = () => Object.assign(new Error('superseded'), { superseded: true });

/** The worker, started on first use; null where none can start. */
function theWorker() {
  if (worker || noWorker) return worker;
  try {
    worker = newWorker();
  } catch (e) {
    reportNoWorker(e);
    noWorker = true;
    return null;
  }
  worker.postMessage({ init: wasmSource() });
  worker.onmessage = ({ data }) => {
    const job = jobs.get(data.id);
    if (!job) return;
    if ('progress' in data) job.onProgress(data.progress);
    else {
      jobs.delete(data.id);
      if (data.error) job.reject(Object.assign(new Error(data.error), { code: data.code, details: data.details }));
      else job.resolve(data);
    }
  };
  // the script did not load (blocked by a policy, or no such file): the jobs run here instead
  worker.onerror = (e) => {
    e.preventDefault();
    reportNoWorker(e);
    worker?.terminate();
    worker = null;
    noWorker = true;
    for (const [id, job] of jobs) here(id, job);
  };
  return worker;
}

/** Runs `job` on the main thread, a step per task, unless a newer job replaces it. */
function here(/** @type {number} */ id, /** @type {Job} */ job) {
  const pause = () =>
    new Promise((resolve, reject) => setTimeout(() => (jobs.has(id) ? resolve(undefined) : reject(superseded())), 0));
  pause()
    .then(
      /** @returns {Promise<unknown>} */
      () =>
        job.optimise
          ? optimiseSteps(job.job, job.onProgress)
          : job.post
            ? postSteps(job.job, job.onProgress, pause)
            : refineSteps(job.job, job.onProgress, pause),
    )
    .then(
      (done) => {
        if (jobs.get(id) !== job) return;
        jobs.delete(id);
        job.resolve(done);
      },
      (e) => {
        if (jobs.get(id) !== job) return;
        jobs.delete(id);
        job.reject(e);
      },
    );
}

/**
 * Refines `segments` with `options` in the worker (or here, where there is none).
 * @param {Float64Array} segments 6 numbers per ruling
 * @param {import('../pkg/ruledlab.js').SubdivideOptions} options RuledSurface.subdivide options, `steps` included
 * @param {(fraction: number) => void} [onProgress]
 * @param {number} [draw]  most rulings to send back (every k-th above it)
 * @returns {Promise<{segments: Float32Array, rulings: number, drawn: number}>}
 */
export function refineInWorker(segments, options, onProgress = () => {}, draw = Infinity) {
  const id = ++nextId;
  supersede();
  return new Promise((resolve, reject) => {
    /** @type {Job} */
    const job = { resolve, reject, onProgress, job: { segments, options, draw } };
    jobs.set(id, job);
    const w = theWorker();
    if (w) w.postMessage({ id, segments, options, draw });
    else here(id, job);
  });
}

/** Drops every pending job (rejected as superseded); a post running in the worker stops it. */
function supersede() {
  let busy = false;
  for (const [old, job] of jobs) {
    jobs.delete(old);
    busy ||= !!job.post || !!job.optimise;
    job.reject(superseded());
  }
  if (busy && worker) {
    worker.terminate();
    worker = null;
  }
}

/**
 * Refines tool poses and posts them as G-code in the worker (or here, where there is none).
 * @param {import('./post-job.js').PostJob} job
 * @param {(fraction: number) => void} [onProgress]
 * @returns {Promise<import('./post-job.js').PostJobResult>}
 */
export function postInWorker(job, onProgress = () => {}) {
  const id = ++nextId;
  supersede();
  return new Promise((resolve, reject) => {
    /** @type {Job} */
    const entry = { resolve, reject, onProgress, job, post: true };
    jobs.set(id, entry);
    const w = theWorker();
    // (the CAM module is started on this thread already: the worker starts its own from the same source)
    if (w) w.postMessage({ id, kind: 'post', ...job, cam: camSource() });
    else here(id, entry);
  });
}

/**
 * Optimises tool poses against a target and posts them in the worker (or here, where there is none).
 * @param {import('./optimise-job.js').OptimiseJob} job
 * @param {(fraction: number) => void} [onProgress]
 * @returns {Promise<import('./optimise-job.js').OptimiseJobResult>}
 */
export function optimiseInWorker(job, onProgress = () => {}) {
  const id = ++nextId;
  supersede();
  return new Promise((resolve, reject) => {
    /** @type {Job} */
    const entry = { resolve, reject, onProgress, job, optimise: true };
    jobs.set(id, entry);
    const w = theWorker();
    if (w) w.postMessage({ id, kind: 'optimise', ...job, cam: camSource() });
    else here(id, entry);
  });
}

/** Stops the work in progress (the view's Cancel): its result will not come. */
export function cancelWork() {
  supersede();
}
