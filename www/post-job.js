// One long job of the milling scene: your tool poses refined step by step and posted as G-code,
// reporting progress by work done (the refinement's steps, then the post's own progress), with
// what the page shows of it — the program, its numbers, every k-th tool axis to draw. Run by the
// worker (worker.js) and, where no worker can start, on the main thread by compute.js: one
// routine for both.
import { cam } from './cam.js';

/**
 * @typedef {object} PostJob
 * @property {Float64Array} poses   6 numbers per given pose (tip, axis)
 * @property {{ radius: number, length: number, end?: 'ball' | 'flat' }} tool
 * @property {import('../pkg/ruledlab.js').SubdivideOptions} refine   steps included
 * @property {import('../pkg/cam/ruledlab_cam.js').GcodeOptions} post
 * @property {number} [draw]   most tool axes to send back (every k-th above it)
 * @property {boolean} [sweep]  also the refined path's own sweep against the post's target
 *
 * @typedef {object} PostJobResult
 * @property {string} text          the program
 * @property {number} poses         of the refined path
 * @property {Float32Array} segments   every k-th tool axis (f32, 6 numbers each)
 * @property {number} every         k
 * @property {number} maxAngleStep  the refined path's largest orientation step (rad)
 * @property {Omit<import('../pkg/cam/ruledlab_cam.js').PostResult, 'text'>} post   what the post did
 * @property {import('../pkg/cam/ruledlab_cam.js').EnvelopeResult} [sweep]   the path's own sweep
 *   against the target (with `sweep` and a target)
 */

/**
 * @param {PostJob} job
 * @param {(fraction: number) => void} progress
 * @param {() => Promise<unknown> | void} [pause]  between steps (the main thread yields there; a
 *   rejection stops the job)
 * @returns {Promise<PostJobResult>}
 */
export async function postSteps({ poses, tool, refine, post, draw = Infinity, sweep = false }, progress, pause) {
  let path = cam().ToolPath.fromPoses(poses, tool);
  try {
    const steps = refine.steps ?? 1;
    // the refinement is about a third of the work, the post the rest
    const total = 2 ** steps - 1 || 1;
    for (let k = 0; k < steps; k++) {
      const next = path.refine({ ...refine, steps: 1 });
      path.free();
      path = next;
      progress((0.3 * (2 ** (k + 1) - 1)) / total);
      await pause?.();
    }
    // the path's own sweep against the target first (the bar at the refinement's end meanwhile)
    const own = sweep && post.target ? { sweep: path.envelopeDeviation(post.target) } : {};
    const { text, ...done } = path.post(post, (/** @type {number} */ f) => progress(0.3 + 0.7 * f));
    const every = Math.max(1, Math.ceil(path.length / draw));
    const segments = every > 1 ? path.everyF32(every) : path.segmentsF32();
    return { text, poses: path.length, segments, every, maxAngleStep: path.quality().maxAngleStep, post: done, ...own };
  } finally {
    path.free();
  }
}
