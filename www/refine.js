// One refinement job of the "Large models" scene: the four-point (or any strip) scheme applied
// step by step, reporting progress by work done (step k costs about 2^k), sending back at most
// `draw` rulings (every k-th above it). Run by the worker (worker.js) and, where no worker can
// start (a sandboxed frame, a Content-Security-Policy without blob: workers), on the main thread
// by compute.js — one routine for both.
import { RuledSurface } from '../pkg/ruledlab.js';

/**
 * @param {{segments: Float64Array, options: import("../pkg/ruledlab.js").SubdivideOptions, draw?: number}} job
 * @param {(fraction: number) => void} progress   after each step
 * @param {() => Promise<unknown> | void} [pause]  between steps (the main thread yields there; a
 *   rejection stops the job)
 * @returns {Promise<{segments: Float32Array, rulings: number, drawn: number}>}
 */
export async function refineSteps({ segments, options, draw = Infinity }, progress, pause) {
  let surface = RuledSurface.fromSegments(segments);
  try {
    const steps = options.steps ?? 1;
    const total = 2 ** steps - 1;
    for (let k = 0; k < steps; k++) {
      const next = surface.subdivide({ ...options, steps: 1 });
      surface.free();
      surface = next;
      progress((2 ** (k + 1) - 1) / total);
      await pause?.();
    }
    const rulings = surface.length;
    const every = Math.max(1, Math.ceil(rulings / draw));
    const out = every > 1 ? surface.everyF32(every) : surface.segmentsF32();
    return { segments: out, rulings, drawn: out.length / 6 };
  } finally {
    surface.free();
  }
}
