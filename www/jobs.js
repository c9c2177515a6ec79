// The long jobs the page hands to its worker (worker.js), by kind: each is one routine, run by the
// worker and, where no worker can start, on the main thread by compute.js.
//   refine      the "Large models" scene's refinement (refine.js)
//   invariants  the invariants of many rulings, for the data scene (invariants-job.js)
//   post        a tool path refined and posted as G-code (post-job.js)
//   optimise    tool poses optimised against a target and posted (optimise-job.js)
import { refineSteps } from './refine.js';
import { invariantsSteps } from './invariants-job.js';
import { postSteps } from './post-job.js';
import { optimiseSteps } from './optimise-job.js';

/**
 * @typedef {'refine' | 'invariants' | 'post' | 'optimise'} JobKind
 * @typedef {(job: any, progress: (fraction: number) => void, pause?: () => Promise<unknown> | void) => Promise<any>} Steps
 */

/** @type {Record<JobKind, Steps>} */
export const STEPS = { refine: refineSteps, invariants: invariantsSteps, post: postSteps, optimise: optimiseSteps };

/** The kinds that need the CAM module (the worker starts it at the first of them). */
export const CAM_KINDS = new Set(['post', 'optimise']);

/**
 * The kinds that run as one long call, stopped only by stopping the worker: when a newer job
 * supersedes one of them, the worker is ended (a new one starts for the next job).
 */
export const LONG_KINDS = new Set(['invariants', 'post', 'optimise']);
