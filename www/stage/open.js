// Opening in a stage, one way for everything: `openView` shows what a request asks for — an
// exercise (read, its numbers drawn, fitted to its scene, what it holds held, the reader's
// progress), or else a scene (with its parameters, the paper's figure, imported data, an edit, a
// camera); the core started first. The page's link, <ruled-view>'s attributes, a course's
// exercise, the exercise API and the Stage's own `open` all go through it. `enterScene` is its
// last step, which a change of language or a return to an exercise's start also takes.
import { start } from '../core.js';
import { startCam } from '../cam.js';
import { SCENES } from '../scenes/index.js';
import { defaults, withChoices } from '../scene.js';
import { Player } from '../ui/player.js';
import { buildControls } from '../ui/controls.js';
import { copyInput, decodeInput, fitsSets } from '../edit/input.js';
import { builtInTask } from '../task/builtin.js';
import { taskFromLink } from '../task/format.js';
import { fitTask } from '../task/check.js';
import { drawTask, randomSeed } from '../task/draw.js';
import { taskErrorText } from '../task/words.js';
import { nextTurn } from '../schedule.js';

/**
 * What to show: an exercise (`task`), or a scene. Without `scene`, an exercise that cannot be
 * read or does not fit its scene throws its TaskError; with one, that is said in a note and the
 * scene opens instead.
 * @typedef {object} ViewRequest
 * @property {import('../scene.js').Scene} [scene]   the scene (if there is no exercise, or it cannot be opened)
 * @property {import('../scene.js').Params} [params]
 * @property {string | import('../task/format.js').Task | null} [task]   an exercise: a built-in id, a "j." link value, or a Task
 * @property {(scene: import('../scene.js').Scene) => import('../scene.js').Params} [progress]   the reader's
 *   parameters in the exercise, read for its scene (it keeps those it lets change)
 * @property {import('../scene.js').Input | null} [taskInput]   the reader's edit in the exercise
 * @property {number | null} [seed]   the seed of the exercise's drawn numbers (none: a new one)
 * @property {AttemptOf} [attempt]   what the reader did in it
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
 * What the reader did in an exercise (task/attempt.js), or a function that finds it for the
 * exercise once read (the page: the attempt this browser kept); used only where its seed is the
 * seed the exercise is drawn with.
 * @typedef {import('../task/attempt.js').Attempt | ((task: import('../task/format.js').Task) => import('../task/attempt.js').Attempt | null) | null} AttemptOf
 */

/**
 * An opening, read from a request: the scene and its parameters, and the exercise with the
 * reader's progress in it, or what a scene alone is opened with.
 * @typedef {object} Opening
 * @property {import('../scene.js').Scene} scene
 * @property {import('../scene.js').Params} params
 * @property {import('../task/format.js').Task | null} exercise
 * @property {Partial<import('../task/panel.js').PanelAttempt> | null} attempt
 * @property {import('../scene.js').Input | null} input
 * @property {number[] | null} camera
 * @property {import('../paper.js').PaperPreset | null} paper
 * @property {import('../scene.js').ImportedData | null | undefined} data
 * @property {string} inputNote
 * @property {boolean} autoplay
 */

/**
 * Opens `request` in `stage`: its exercise, or — without one, or where it cannot be read or does
 * not fit its scene (said in a note) — its scene. Resolves to the notes (said in the view unless
 * an opening begun meanwhile ended this one).
 * @param {import('../stage.js').Stage} stage
 * @param {ViewRequest} request
 * @returns {Promise<import('../stage.js').Notes>}
 */
export async function openView(stage, request) {
  const notes = [...(request.notes ?? [])];
  /** @type {Opening | null} */
  let opening = null;
  if (request.task) {
    try {
      opening = await readExercise(stage, request.task, request);
    } catch (e) {
      if (!request.scene) throw e;
      const note = request.source === 'element' ? 'element.note.badTask' : 'note.badTask';
      notes.push({ key: 'task', note, vars: { reason: taskErrorText(e, stage.i18n) } });
    }
  }
  if (!opening) {
    const scene = /** @type {import('../scene.js').Scene} */ (request.scene);
    opening = {
      scene,
      params: { ...defaults(scene), ...(request.params ?? {}) },
      exercise: null,
      attempt: null,
      input: request.input ?? null,
      camera: request.camera ?? null,
      paper: request.paper && request.paper.scene === scene.id ? request.paper : null,
      data: request.data,
      inputNote: request.inputNote ?? '',
      autoplay: !!request.autoplay,
    };
  }
  await show(stage, opening, notes);
  return notes;
}

/**
 * Reads the exercise `value` for `stage`: drawn with the request's seed (or the kept attempt's,
 * or a new one), fitted to its scene (which computes it: the module it needs started first), at
 * its start with what the reader may change from `request`'s progress; throws a TaskError (its
 * reason said in the stage's language by task/words.js) where it cannot be read or does not fit.
 * @param {import('../stage.js').Stage} stage
 * @param {string | import('../task/format.js').Task} value
 * @param {ViewRequest} request
 * @returns {Promise<Opening>}
 */
async function readExercise(stage, value, request) {
  const read = typeof value === 'string' ? taskFromLink(value, builtInTask) : value;
  if (SCENES.find((x) => x.id === read.scene)?.needs?.includes('cam')) await startCam();
  const kept = typeof request.attempt === 'function' ? request.attempt(read) : (request.attempt ?? null);
  const task = drawTask(read, request.seed ?? kept?.seed ?? read.drawn?.seed ?? randomSeed());
  // the attempt belongs to these numbers (or the exercise draws none)
  const attempt = kept && (kept.seed ?? null) === (task.drawn?.seed ?? null) ? kept : null;
  const { t, format, lang } = stage.i18n;
  const scene = fitTask(task, SCENES, (params, input) => {
    const s = /** @type {import('../scene.js').Scene} */ (SCENES.find((x) => x.id === task.scene));
    return s.create(withChoices(s, { ...task.params, ...params }), { t, format, lang, ...(input ? { input } : {}) });
  });
  // the reader's progress: what the request brings (a link, a course), else what she did in the
  // attempt kept for these numbers — a return to an exercise shows her figure, not its start
  const progress = { ...(attempt?.params ?? {}), ...(request.progress?.(scene) ?? {}) };
  const changed = Object.fromEntries(Object.entries(progress).filter(([k]) => task.change.includes(k)));
  const start = task.input ? decodeInput(task.input) : null;
  const edit = request.taskInput ?? (attempt?.input ? decodeInput(attempt.input) : null);
  return {
    scene,
    params: { ...defaults(scene), ...withChoices(scene, task.params), ...changed },
    exercise: task,
    attempt,
    input: task.change.includes('handles') && edit ? edit : start,
    camera: request.camera ?? null,
    paper: null,
    data: undefined,
    inputNote: '',
    autoplay: false,
  };
}

/**
 * Shows `opening` in `stage` (and says `notes`): the core (and the CAM module where the scene needs it) started, the
 * scene entered — in steps on the page's first opening — with the exercise and what it holds, the
 * notes said, the exercise's panel shown, autoplay unless the reader prefers reduced motion.
 * Resolves to false where an opening begun while this one was in its steps ended it.
 * @param {import('../stage.js').Stage} stage
 * @param {Opening} opening
 * @param {import('../stage.js').Notes} notes
 */
async function show(stage, opening, notes) {
  const { scene, params, exercise, input, camera } = opening;
  // (the figure shown is no longer the one asked for: ready again once this one is computed)
  delete stage.els.root.dataset.ready;
  if (!exercise) stage.exercise.panel.show(null);
  try {
    await start();
    if (scene.needs?.includes('cam')) await startCam();
  } catch (e) {
    stage.fail(e);
    throw e;
  }
  /** @type {EnterOptions} */
  const options = {
    camera,
    input,
    opening: {
      exercise,
      paper: opening.paper,
      inputNote: opening.inputNote,
      ...(opening.data !== undefined ? { data: opening.data } : {}),
    },
  };
  const fits = stage.inSteps
    ? await enterInSteps(stage, scene, params, options)
    : enterScene(stage, scene, params, options);
  // (an opening begun while this one was in its steps has shown its scene: this one ends)
  if (fits === null || stage.task !== exercise) return false;
  if (!fits) notes.push({ key: 'input', note: 'note.badInput' });
  // an exercise's constraint that cannot hold is said, and lifted
  for (const { handle, why } of stage.edit.lifted)
    notes.push({ key: 'edit', note: `snap.lifted.${why}`, vars: { handle } });
  stage.showNotes(notes);
  if (exercise) {
    stage.exercise.panel.show(exercise, opening.attempt);
    // the exercise is at the top of the panel: a panel scrolled down for the figure before shows it
    stage.els.panel.scrollTop = 0;
    stage.edit.show();
  }
  if (opening.autoplay && !Player.reducedMotion()) {
    const key = stage.player.playableKey();
    if (key) stage.player.toggle(key);
  }
  return true;
}

/**
 * Leaves the exercise shown in `stage` (if any): the scene stays, as it is, with nothing held.
 * @param {import('../stage.js').Stage} stage
 */
export function leaveExercise(stage) {
  if (!stage.task) return;
  stage.exercise.panel.show(null);
  if (stage.scene)
    enterScene(stage, stage.scene, stage.params, {
      camera: stage.viewer.camera.toArray(),
      fit: false,
      input: stage.input,
      opening: { exercise: null },
    });
}

/**
 * How a scene is shown (Stage.enter).
 * @typedef {object} EnterOptions
 * @property {number[] | null} [camera]   the camera to show it from (default: fitted, if `fit`)
 * @property {boolean} [fit]
 * @property {import('../scene.js').Input | null} [input]   an edit to show (kept only where it fits the scene's handles)
 * @property {boolean} [history]   keep the edit's undo steps (a change of language)
 * @property {Partial<Omit<Extract<import('../store.js').StageChange, {type: 'open'}>, 'type' | 'scene' | 'params' | 'input'>>} [opening]
 *   what the opening sets besides the scene, its parameters and the input (store.js's 'open')
 */

/** The latest opening of each stage: one still in its steps ends when another begins. @type {WeakMap<object, object>} */
const openings = new WeakMap();

/**
 * Shows `scene` with `params` in `stage`: its texts and controls, then what the core computes,
 * the built-in input first (its handles set the box they stay in and say what was edited), then
 * `input` where it fits the scene's handles. Returns whether the input given (if any) fits.
 * @param {import('../stage.js').Stage} stage
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {EnterOptions} options
 */
export function enterScene(stage, scene, params, options) {
  const token = {};
  openings.set(stage, token);
  // (an opening still in its steps ends here: this one shows everything now)
  stage.els.root.classList.remove('rl-opening');
  const steps = enterSteps(stage, scene, params, options, token);
  let step = steps.next();
  while (!step.done) step = steps.next();
  return step.value ?? true;
}

/**
 * enterScene in tasks of their own (the page's first opening: no task of the start blocks the
 * reader for long): the texts and controls, the computation, the rest — the panel's new parts
 * kept invisible until the last, in their places (nothing painted moves). A later opening of the
 * stage ends one still in its steps: then null.
 * @param {import('../stage.js').Stage} stage
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {EnterOptions} options
 */
export async function enterInSteps(stage, scene, params, options) {
  const token = {};
  openings.set(stage, token);
  const steps = enterSteps(stage, scene, params, options, token);
  const { root } = stage.els;
  root.classList.add('rl-opening');
  try {
    for (let step = steps.next(); ; step = steps.next()) {
      if (step.done) return step.value;
      await nextTurn();
    }
  } finally {
    if (openings.get(stage) === token) root.classList.remove('rl-opening');
  }
}

/**
 * The steps of enterScene: each `yield` is a place where the work may wait for a later task; an
 * opening begun since ends this one there.
 * @param {import('../stage.js').Stage} stage
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {EnterOptions} options
 * @param {object} token   the opening's (in `openings` while it is the latest)
 * @returns {Generator<void, boolean | null, void>}   null where an opening begun since ended it
 */
function* enterSteps(
  stage,
  scene,
  params,
  { camera = null, fit = true, input = null, history = false, opening = {} },
  token,
) {
  const superseded = () => openings.get(stage) !== token;
  const sceneChanged = stage.scene !== scene;
  if (sceneChanged) stage.player.stop();
  if (!history) stage.editor.cancel();
  stage.dispatch({ type: 'open', scene, params, input: null, ...opening });
  stage.preview(scene);
  // the panel (an exercise may hide the explanation where it would say the answer)
  stage.showPanel(stage.state);
  const controls = buildControls(stage.els.form, scene, stage.params, stage.i18n, {
    onChange: (key, value, ended) => stage.setParam(key, value, ended),
    onPlay: (key) => stage.player.toggle(key),
    fixed: (p) => stage.heldReason(p.key),
  });
  stage.controls = controls;
  // an exercise's hidden parameters (an answer-revealing layer) are not shown at all
  for (const key of stage.task?.hide ?? []) {
    const row = controls.rows.get(key)?.row;
    if (row) row.hidden = true;
  }
  stage.player.render(stage.state);
  stage.paperCard.render(stage.state);
  yield;
  if (superseded()) return null;
  // (an edit to show comes next: the figure is said as edited, not as built without it)
  if (input) stage.results.hold();
  const editable = stage.compute({ fit: fit && !camera })?.input;
  yield;
  if (superseded()) {
    stage.results.hold(false);
    return null;
  }
  if (history) stage.editor.show(editable);
  else stage.edit.enter(editable, sceneChanged);
  const fits = !input || (!!editable && fitsSets(input, editable.sets));
  if (input && fits) {
    // (drawn as every change is: the core computes on it, the controls follow)
    stage.dispatch({ type: 'input', input: copyInput(input) });
  }
  if (input) stage.results.release(stage.state);
  stage.edit.show();
  // (measured once everything the scene shows is in the page: one layout, not one per part)
  controls.fit();
  if (camera) {
    stage.viewer.camera.fromArray(camera);
    stage.viewer.requestRender();
  }
  return fits;
}
