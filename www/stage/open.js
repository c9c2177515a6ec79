// Opening in a stage: a scene (with its parameters, the paper's figure, imported data, an edit,
// a camera; the core started first) or an exercise (its start, what it holds, the reader's
// progress) — the stage's state changes here and in stage.js only. And one function for what a
// link (the page's address) or an element (its attributes) asks for, so both read an exercise the
// same way.
import { start } from '../core.js';
import { startCam } from '../cam.js';
import { SCENES } from '../scenes/index.js';
import { defaults, withChoices } from '../scene.js';
import { Player } from '../ui/player.js';
import { buildControls } from '../ui/controls.js';
import { copyInput, fitsSets } from '../edit/input.js';
import { builtInTask } from '../task/builtin.js';
import { taskFromLink } from '../task/format.js';
import { fitTask } from '../task/check.js';
import { drawTask, randomSeed } from '../task/draw.js';
import { taskErrorText } from '../task/words.js';
import { nextTask } from '../schedule.js';

/**
 * What to show.
 * @typedef {object} ViewRequest
 * @property {import('../scene.js').Scene} scene   the scene (if there is no exercise, or it cannot be opened)
 * @property {import('../scene.js').Params} params
 * @property {string | import('../task/format.js').Task | null} [task]   an exercise
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
        seed: request.seed ?? null,
        attempt: request.attempt ?? null,
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
 * @param {{params?: (scene: import('../scene.js').Scene) => import('../scene.js').Params, input?: import('../scene.js').Input | null, camera?: number[] | null, notes?: import('../stage.js').Notes, seed?: number | null, attempt?: AttemptOf}} [progress]
 *   the reader's parameters (read for the exercise's scene), edit, camera; notes to show; the
 *   seed of the numbers drawn (none: a new one) and what she did (answers, hints, checks)
 */
export async function openExercise(stage, value, progress = {}) {
  const read = typeof value === 'string' ? taskFromLink(value, builtInTask) : value;
  // (fitting it to its scene computes the scene: the module it needs first)
  if (SCENES.find((x) => x.id === read.scene)?.needs?.includes('cam')) await startCam();
  const kept = typeof progress.attempt === 'function' ? progress.attempt(read) : (progress.attempt ?? null);
  const task = drawTask(read, progress.seed ?? kept?.seed ?? read.drawn?.seed ?? randomSeed());
  // the attempt belongs to these numbers (or the exercise draws none)
  const attempt = kept && (kept.seed ?? null) === (task.drawn?.seed ?? null) ? kept : null;
  const { t, format, lang } = stage.i18n;
  const scene = fitTask(task, SCENES, (params, input) => {
    const s = /** @type {import('../scene.js').Scene} */ (SCENES.find((x) => x.id === task.scene));
    return s.create(withChoices(s, { ...task.params, ...params }), { t, format, lang, ...(input ? { input } : {}) });
  });
  const { params, seed: _, attempt: __, ...rest } = progress;
  await stage.openTask(task, scene, { ...rest, attempt, params: params?.(scene) ?? {} });
}

/**
 * Opens `scene` in `stage` (Stage.open): the core started, its parameters (missing ones take
 * their defaults), the paper's figure if it is this scene's, the notes said, autoplay unless the
 * reader prefers reduced motion. Opening a scene leaves the exercise shown, unless `options.task`.
 * Resolves to true, or false where an opening begun while this one was in its steps ended it.
 * @param {import('../stage.js').Stage} stage
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {import('../stage.js').OpenOptions} options
 * @returns {Promise<boolean>}
 */
export async function openScene(stage, scene, params, options) {
  // (the figure shown is no longer the one asked for: ready again once this one is computed)
  delete stage.els.root.dataset.ready;
  if (!options.task) leaveTask(stage);
  try {
    await start();
    if (scene.needs?.includes('cam')) await startCam();
  } catch (e) {
    stage.fail(e);
    throw e;
  }
  const notes = [...(options.notes ?? [])];
  const input = options.input ?? null;
  /** @type {EnterOptions} */
  const enterOptions = {
    camera: options.camera ?? null,
    input,
    // what the opening sets besides the scene and its parameters (store.js's 'open')
    opening: {
      ...(options.data !== undefined ? { data: options.data } : {}),
      paper: options.paper && options.paper.scene === scene.id ? options.paper : null,
      inputNote: options.inputNote ?? '',
      ...(options.task ? {} : { exercise: null }),
    },
  };
  const all = { ...defaults(scene), ...params };
  const fits = stage.inSteps
    ? await enterInSteps(stage, scene, all, enterOptions)
    : stage.enter(scene, all, enterOptions);
  // (an opening begun while this one was in its steps has shown its scene: this one ends)
  if (fits === null) return false;
  if (!fits) notes.push({ key: 'input', note: 'note.badInput' });
  // an exercise's constraint that cannot hold is said, and lifted
  for (const { handle, why } of stage.edit.lifted)
    notes.push({ key: 'edit', note: `snap.lifted.${why}`, vars: { handle } });
  stage.showNotes(notes);
  if (options.autoplay && !Player.reducedMotion()) {
    const key = stage.player.playableKey();
    if (key) stage.player.toggle(key);
  }
  return true;
}

/**
 * Opens `task` in `stage` (Stage.openTask): its scene at its start, what it lets change (its
 * parameters from `state`, and the reader's edit where handles may move), the rest held; null
 * leaves the exercise (the scene stays).
 * @param {import('../stage.js').Stage} stage
 * @param {import('../task/format.js').Task | null} task
 * @param {import('../scene.js').Scene | null} scene
 * @param {{params?: import('../scene.js').Params, input?: import('../scene.js').Input | null, camera?: number[] | null, notes?: import('../stage.js').Notes, attempt?: Partial<import('../task/panel.js').PanelAttempt> | null}} state
 */
export async function openTask(stage, task, scene, state) {
  if (!task || !scene) {
    leaveTask(stage);
    if (stage.scene)
      stage.enter(stage.scene, stage.params, { camera: stage.viewer.camera.toArray(), fit: false, input: stage.input });
    return;
  }
  stage.dispatch({ type: 'exercise', exercise: task });
  const kept = Object.fromEntries(Object.entries(state.params ?? {}).filter(([k]) => task.change.includes(k)));
  const input = task.change.includes('handles') && state.input ? state.input : stage.exercise.startInput();
  const shown = await openScene(
    stage,
    scene,
    { ...withChoices(scene, task.params), ...kept },
    { camera: state.camera ?? null, input, notes: state.notes ?? [], task: true, paper: null },
  );
  // (another opening, begun while this one was in its steps, has the stage now)
  if (!shown || stage.task !== task) return;
  stage.exercise.panel.show(task, state.attempt ?? null);
  // the exercise is at the top of the panel: a panel scrolled down for the figure before shows it
  stage.els.panel.scrollTop = 0;
  stage.edit.show();
}

/** Leaves the exercise shown in `stage` (if any); the scene stays. @param {import('../stage.js').Stage} stage */
function leaveTask(stage) {
  if (!stage.task) return;
  stage.dispatch({ type: 'exercise', exercise: null });
  stage.exercise.panel.show(null);
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
      await nextTask();
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
  // (an exercise may hide the explanation where it would say the answer)
  stage.els.text.hidden = !stage.showText || !!stage.task?.hide.includes('text');
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
  const editable = stage.compute({ fit: fit && !camera })?.input;
  yield;
  if (superseded()) return null;
  if (history) stage.editor.show(editable);
  else stage.edit.enter(editable, sceneChanged);
  const fits = !input || (!!editable && fitsSets(input, editable.sets));
  if (input && fits) {
    // (drawn as every change is: the core computes on it, the controls follow)
    stage.dispatch({ type: 'input', input: copyInput(input) });
  }
  stage.edit.show();
  // (measured once everything the scene shows is in the page: one layout, not one per part)
  controls.fit();
  if (camera) {
    stage.viewer.camera.fromArray(camera);
    stage.viewer.requestRender();
  }
  return fits;
}
