// One optimisation of the milling scene: the refined tool poses fitted to the target (the core's
// optimisePoses: the deviation of the path's sweep from the target in least squares, the
// variational schemes' fairness keeping the poses smooth), then posted as G-code to measure the
// program as posted, reporting progress (the optimisation's rounds, then the post). Run by the
// worker (worker.js) and, where no worker can start, on the main thread by compute.js: one
// routine for both.
import { cam } from './cam.js';

/**
 * @typedef {object} OptimiseJob
 * @property {Float64Array} poses   6 numbers per pose of the refined path (tip, unit axis)
 * @property {{ radius: number, length: number, end?: 'ball' | 'flat' }} tool
 * @property {Float64Array} target  the target's points, 3 numbers each (the poses' units)
 * @property {import('../pkg/cam/ruledlab_cam.js').GcodeOptions} post   the post's options (the target added here)
 *
 * @typedef {{ gouge: number, leave: number, rms: number, largest: number }} Deviations
 *
 * @typedef {object} OptimiseJobResult
 * @property {Float32Array} segments   the optimised tool axes (f32, 6 numbers each: tip, tip + L·axis)
 * @property {number} rounds           rounds the optimisation took
 * @property {Deviations} before       the target's deviation from the given path's own sweep (the poses' units)
 * @property {Deviations} after        … from the optimised path's own sweep
 * @property {Deviations | null} posted   … from the program posted of the optimised poses (the program's units)
 */

/**
 * @param {OptimiseJob} job
 * @param {(fraction: number) => void} progress
 * @returns {Promise<OptimiseJobResult>}
 */
export async function optimiseSteps({ poses, tool, target, post }, progress) {
  const path = cam().ToolPath.fromPoses(poses, tool);
  /** @type {import('../pkg/cam/ruledlab_cam.js').ToolPath | null} */
  let optimised = null;
  try {
    // the optimisation is most of the work, the post the rest
    const r = cam().optimisePoses(path, target, {}, (/** @type {number} */ f) => progress(0.8 * f));
    optimised = cam().ToolPath.fromPoses(r.poses, tool);
    const d = optimised.post({ ...post, target }, (/** @type {number} */ f) => progress(0.8 + 0.2 * f)).deviation;
    return {
      segments: optimised.segmentsF32(),
      rounds: r.rounds,
      before: r.before,
      after: r.after,
      posted: d ? { gouge: d.gouge, leave: d.leave, rms: d.rms, largest: d.largest } : null,
    };
  } finally {
    path.free();
    optimised?.free();
  }
}
