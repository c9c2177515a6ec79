// Runs the page's long jobs (jobs.js: a refinement, the invariants of many rulings, a tool path's
// post, an optimisation of its poses) in a Web Worker (www/worker.js, with its own wasm
// instance), one job at a time; a newer job supersedes an older one, whose result is dropped.
// Where no worker can start — a sandboxed frame, a page whose Content-Security-Policy forbids the
// worker's script — the same job runs on the main thread, yielding between steps. A job that is
// one long call (LONG_KINDS) is stopped by a newer job or cancelWork() by ending the worker (a
// new one starts for the next job).
import { newWorker, reportNoWorker, wasmSource } from './core.js';
import { camSource } from './cam.js';
import { STEPS, CAM_KINDS, LONG_KINDS } from './jobs.js';

/** @type {Worker | null} */
let worker = null;
/** Whether workers cannot start here (then every job runs on the main thread). */
let noWorker = false;
let nextId = 0;
/**
 * @typedef {{resolve: (v: any) => void, reject: (e: any) => void, onProgress: (f: number) => void, kind: import('./jobs.js').JobKind, job: any}} Job
 *   job: what the routine of its kind takes (jobs.js)
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
      () => STEPS[job.kind](job.job, job.onProgress, pause),
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
 * Runs `job` of `kind` in the worker (or here, where there is none), superseding the job before.
 * @param {import('./jobs.js').JobKind} kind @param {any} job
 * @param {(fraction: number) => void} onProgress
 * @returns {Promise<any>}
 */
function run(kind, job, onProgress) {
  const id = ++nextId;
  supersede();
  return new Promise((resolve, reject) => {
    /** @type {Job} */
    const entry = { resolve, reject, onProgress, kind, job };
    jobs.set(id, entry);
    const w = theWorker();
    // (a CAM job's module is started on this thread already: the worker starts its own from the same source)
    if (w) w.postMessage({ id, kind, ...job, ...(CAM_KINDS.has(kind) ? { cam: camSource() } : {}) });
    else here(id, entry);
  });
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
  return run('refine', { segments, options, draw }, onProgress);
}

/**
 * The invariants of many rulings, reduced to what the data scene shows, in the worker (or here).
 * @param {import('./invariants-job.js').InvariantsJob} job
 * @param {(fraction: number) => void} [onProgress]
 * @returns {Promise<import('./invariants-job.js').InvariantsJobResult>}
 */
export function invariantsInWorker(job, onProgress = () => {}) {
  return run('invariants', job, onProgress);
}

/** Drops every pending job (rejected as superseded); a long one running in the worker stops it. */
function supersede() {
  let busy = false;
  for (const [old, job] of jobs) {
    jobs.delete(old);
    busy ||= LONG_KINDS.has(job.kind);
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
  return run('post', job, onProgress);
}

/**
 * Optimises tool poses against a target and posts them in the worker (or here, where there is none).
 * @param {import('./optimise-job.js').OptimiseJob} job
 * @param {(fraction: number) => void} [onProgress]
 * @returns {Promise<import('./optimise-job.js').OptimiseJobResult>}
 */
export function optimiseInWorker(job, onProgress = () => {}) {
  return run('optimise', job, onProgress);
}

/** Stops the work in progress (the view's Cancel): its result will not come. */
export function cancelWork() {
  supersede();
}
