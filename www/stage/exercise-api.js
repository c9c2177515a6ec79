// What a program may do with the exercise shown in a stage — <ruled-view>'s `exercise` property
// and the H5P content type (course/h5p-type.js) use it: check as the Check button does, show the
// solution, start over, and read or restore the attempt (seed, what the reader changed, her
// answers, hints and checks: task/attempt.js).
import { encodeInput, decodeInput } from '../edit/input.js';
import { openView } from './open.js';

/**
 * @typedef {object} ExerciseApi
 * @property {string} id           the exercise's id
 * @property {number} maxScore     how many conditions its goal has
 * @property {number | null} seed  the seed of the numbers drawn (null: it draws none)
 * @property {() => import('../task/panel.js').TaskReport | null} check   a check, reported as the Check button's
 * @property {() => import('../task/panel.js').TaskReport | null} showSolution   the solution, shown with its
 *   conditions (null: it has none, or it is not offered yet); it counts for nothing, nor does any check after it
 * @property {() => void} startOver   back to the start, answers, hints and checks cleared (a solution shown stays shown)
 * @property {() => import('../task/attempt.js').Attempt} attempt   the attempt as it stands
 * @property {(attempt: import('../task/attempt.js').Attempt) => Promise<void>} restore   an attempt read by task/attempt.js
 */

/**
 * The attempt at the exercise shown in `stage` (null: none shown).
 * @param {import('../stage.js').Stage} stage
 * @returns {import('../task/attempt.js').Attempt | null}
 */
export function attemptOf(stage) {
  const task = stage.task;
  if (!task) return null;
  const params = Object.fromEntries(Object.entries(stage.params).filter(([k]) => task.change.includes(k)));
  const input = task.change.includes('handles') && stage.input ? encodeInput(stage.input) : null;
  return { seed: task.drawn?.seed ?? null, params, input, ...stage.exercise.panel.attempt() };
}

/**
 * The exercise of `stage` for a program, or null when none is shown.
 * @param {import('../stage.js').Stage} stage
 * @returns {ExerciseApi | null}
 */
export function exerciseApi(stage) {
  const task = stage.task;
  if (!task) return null;
  const panel = stage.exercise.panel;
  return {
    id: task.id,
    maxScore: task.goal.length,
    seed: task.drawn?.seed ?? null,
    check: () => panel.check(),
    showSolution: () => panel.solve(),
    // (a solution shown stays shown: what is checked after it in this attempt still counts for nothing)
    startOver: () => {
      panel.show(task, { shown: panel.shown });
      stage.exercise.start();
    },
    attempt: () => /** @type {import('../task/attempt.js').Attempt} */ (attemptOf(stage)),
    restore: (attempt) =>
      openView(stage, {
        task: task.drawn?.from ?? task,
        seed: attempt.seed ?? task.drawn?.seed ?? null,
        progress: () => attempt.params,
        taskInput: attempt.input ? decodeInput(attempt.input) : null,
        camera: stage.viewer.camera.toArray(),
        attempt,
      }).then(() => {}),
  };
}
