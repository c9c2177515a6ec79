// Opening what a link or an element asks for, in a stage: an exercise (a built-in one's id, the
// page's "j." link value, or a Task) with the reader's progress, or else a scene with its
// parameters, the paper's figure, an edit and a camera. One function for the page (its address)
// and for <ruled-view> (its attributes), so both read an exercise the same way.
import { SCENES } from '../scenes/index.js';
import { withChoices } from '../scene.js';
import { builtInTask } from '../task/builtin.js';
import { taskFromLink } from '../task/format.js';
import { fitTask } from '../task/check.js';
import { taskErrorText } from '../task/words.js';

/**
 * What to show.
 * @typedef {object} ViewRequest
 * @property {import('../scene.js').Scene} scene   the scene (if there is no exercise, or it cannot be opened)
 * @property {import('../scene.js').Params} params
 * @property {string | import('../task/format.js').Task | null} [task]   an exercise
 * @property {(scene: import('../scene.js').Scene) => import('../scene.js').Params} [progress]   the reader's
 *   parameters in the exercise, read for its scene (it keeps those it lets change)
 * @property {import('../scene.js').Input | null} [taskInput]   the reader's edit in the exercise
 * @property {import('../paper.js').PaperPreset | null} [paper]
 * @property {number[] | null} [camera]
 * @property {import('../scene.js').Input | null} [input]
 * @property {string} [inputNote]
 * @property {import('../scene.js').ImportedData | null} [data]
 * @property {import('../stage.js').Notes} [notes]   values that were not used, said in the view
 * @property {boolean} [autoplay]
 * @property {'link' | 'element'} [source]   where the request came from (the notes say "the link" or "the element")
 */

/**
 * Opens `request` in `stage`: its exercise, or — without one, or where it cannot be read or does
 * not fit its scene (said in a note) — its scene. Resolves to the notes shown.
 * @param {import('../stage.js').Stage} stage
 * @param {ViewRequest} request
 */
export async function openView(stage, request) {
  const notes = [...(request.notes ?? [])];
  if (request.task) {
    try {
      await openExercise(stage, request.task, {
        params: request.progress ?? (() => ({})),
        input: request.taskInput ?? null,
        camera: request.camera ?? null,
        notes,
      });
      return notes;
    } catch (e) {
      const note = request.source === 'element' ? 'element.note.badTask' : 'note.badTask';
      notes.push({ key: 'task', note, vars: { reason: taskErrorText(e, stage.i18n) } });
    }
  }
  await stage.open(request.scene, request.params, {
    camera: request.camera ?? null,
    data: request.data,
    notes,
    autoplay: request.autoplay,
    paper: request.paper ?? null,
    input: request.input ?? null,
    inputNote: request.inputNote,
  });
  return notes;
}

/**
 * Opens an exercise in `stage` with the reader's `progress`; throws a TaskError (its reason said
 * in the stage's language by task/words.js) where it cannot be read or does not fit its scene.
 * @param {import('../stage.js').Stage} stage
 * @param {string | import('../task/format.js').Task} value   a built-in id, a "j." link value, or a Task
 * @param {{params?: (scene: import('../scene.js').Scene) => import('../scene.js').Params, input?: import('../scene.js').Input | null, camera?: number[] | null, notes?: import('../stage.js').Notes}} [progress]
 *   the reader's parameters (read for the exercise's scene), edit, camera; notes to show
 */
export async function openExercise(stage, value, progress = {}) {
  const task = typeof value === 'string' ? taskFromLink(value, builtInTask) : value;
  const { t, format, lang } = stage.i18n;
  const scene = fitTask(task, SCENES, (params, input) => {
    const s = /** @type {import('../scene.js').Scene} */ (SCENES.find((x) => x.id === task.scene));
    return s.create(withChoices(s, { ...task.params, ...params }), { t, format, lang, ...(input ? { input } : {}) });
  });
  const { params, ...rest } = progress;
  await stage.openTask(task, scene, { ...rest, params: params?.(scene) ?? {} });
}
