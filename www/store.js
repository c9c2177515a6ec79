// The state of a view and the one place it changes: a Stage's scene, parameters, the reader's
// edit of its input, the exercise, the paper's figure, imported data, the language and what the
// panel shows. The state is a frozen object; `dispatch(change)` is its only writer — it computes
// the next state from the change (`reduce`, a pure function) and hands both to the Stage, which
// asks the core for what the state shows and lets each part of the screen draw from the state and
// what the core built (stage.js). Nothing else writes the state; a part that wants a change
// dispatches one. tests/node/store.test.mjs holds the reducer to its rules,
// tests/node/architecture.test.mjs holds the rest of www/ to writing nothing of it.
import { holdProjection, sameProjection } from './klein-projection.js';

/**
 * @typedef {object} StageState
 * @property {import('./scene.js').Scene | null} scene      the scene shown (null before the first opening)
 * @property {import('./scene.js').Params} params           its parameters
 * @property {import('./scene.js').Input | null} input      the reader's edit of its input (null: the built-in input)
 * @property {string} inputNote        the i18n key of a note about the edit (kept in this tab), or ''
 * @property {import('./task/format.js').Task | null} exercise   the exercise being done, if any
 * @property {import('./paper.js').PaperPreset | null} paper      the paper's figure shown, if any
 * @property {import('./scene.js').ImportedData | null} data      your data (the "data" and milling scenes)
 * @property {string} lang             the language of the view's words (a code of i18n/index.js)
 * @property {boolean} controls        the panel shows the controls and the readout
 * @property {boolean} text            the panel shows the explanation
 * @property {boolean} editable        the reader may drag the scene's handles (an exercise decides in it)
 * @property {'space' | 'split'} view   the 3D view alone, or the Klein view of the scene's lines beside it
 * @property {{mix: number, turn: number, unit: number} | null} projection   the image of P⁵ the
 *   Klein view beside draws in, as the reader steered it (null: the scene's own, or KLEIN_PROJECTION);
 *   each number held in its range and on its step (KLEIN_RANGES)
 * @property {number | null} marked   the line marked in both views (of the lines the scene exports), if any;
 *   forgotten when the lines change (an opening, a parameter, an edit) or the view closes
 * @property {string | null} changed   the parameter the reader changed last (an error names its field)
 * @property {boolean} moving          the input is being moved (a drag or a held key that has not ended)
 *
 * A change of the state (what `dispatch` takes):
 * @typedef {{type: 'open', scene: import('./scene.js').Scene, params: import('./scene.js').Params, input?: import('./scene.js').Input | null, exercise?: import('./task/format.js').Task | null,
 *   paper?: import('./paper.js').PaperPreset | null, data?: import('./scene.js').ImportedData | null, inputNote?: string}
 *   | {type: 'param', key: string, value: number | string | boolean}
 *   | {type: 'params', params: import('./scene.js').Params}
 *   | {type: 'input', input: import('./scene.js').Input | null, moving?: boolean}
 *   | {type: 'inputNote', note: string}
 *   | {type: 'exercise', exercise: import('./task/format.js').Task | null}
 *   | {type: 'lang', lang: string}
 *   | {type: 'panel', controls: boolean, text: boolean}
 *   | {type: 'editable', on: boolean}
 *   | {type: 'view', view: 'space' | 'split'}
 *   | {type: 'mark', line: number | null}
 *   | {type: 'projection', projection: {mix: number, turn: number, unit: number} | null}} StageChange
 */

/** The state of a view that shows nothing yet. @returns {StageState} */
export function initialState(/** @type {Partial<StageState>} */ given = {}) {
  return Object.freeze({
    scene: null,
    params: {},
    input: null,
    inputNote: '',
    exercise: null,
    paper: null,
    data: null,
    lang: 'en',
    controls: true,
    text: true,
    editable: false,
    view: 'space',
    projection: null,
    marked: null,
    changed: null,
    moving: false,
    ...given,
  });
}

/**
 * Why parameter `key` is held where it is (an i18n key), or null: an exercise holds what it does
 * not let change, an edit of the input holds what would replace it. A held parameter changes by
 * no route — slider, − / +, its field, play, single step, setParams.
 * @param {StageState} state
 * @param {string} key
 */
export function heldReason(state, key) {
  if (state.exercise && !state.exercise.change.includes(key)) return 'task.reason.locked';
  if (state.input && !state.exercise && state.scene?.fixed?.includes(key)) return 'edit.reason.fixed';
  return null;
}

/**
 * The state after `change` (the same object where it changes nothing). Pure: it reads only its
 * arguments, and the scene's own rules (a parameter's `sets`).
 * @param {StageState} state
 * @param {StageChange} change
 * @returns {StageState}
 */
export function reduce(state, change) {
  switch (change.type) {
    case 'open':
      return {
        ...state,
        scene: change.scene,
        params: { ...change.params },
        input: change.input ?? null,
        exercise: change.exercise === undefined ? state.exercise : change.exercise,
        paper: change.paper === undefined ? state.paper : change.paper,
        data: change.data === undefined ? state.data : change.data,
        inputNote: change.inputNote ?? state.inputNote,
        changed: null,
        moving: false,
        marked: null,
      };
    case 'param': {
      const { key, value } = change;
      if (!state.scene || heldReason(state, key) || state.params[key] === value) return state;
      const p = state.scene.params.find((q) => q.key === key);
      // a choice may set others with it (a preset's values)
      return {
        ...state,
        params: { ...state.params, [key]: value, ...(p?.sets?.(value, state.params) ?? {}) },
        changed: key,
        // (other lines now: the mark would name another)
        marked: null,
      };
    }
    case 'params':
      return { ...state, params: { ...change.params }, marked: null };
    case 'input':
      return { ...state, input: change.input, moving: !!change.moving, marked: null };
    case 'inputNote':
      return state.inputNote === change.note ? state : { ...state, inputNote: change.note };
    case 'exercise':
      return state.exercise === change.exercise ? state : { ...state, exercise: change.exercise };
    case 'lang':
      return state.lang === change.lang ? state : { ...state, lang: change.lang };
    case 'panel':
      return state.controls === change.controls && state.text === change.text
        ? state
        : { ...state, controls: change.controls, text: change.text };
    case 'editable':
      return state.editable === change.on ? state : { ...state, editable: change.on };
    case 'view':
      return state.view === change.view ? state : { ...state, view: change.view, marked: null };
    case 'mark':
      return state.marked === change.line ? state : { ...state, marked: change.line };
    case 'projection': {
      // (held in its ranges: a change from a link, an attribute or a slider alike)
      const projection = change.projection && holdProjection(change.projection).projection;
      return sameProjection(state.projection, projection) ? state : { ...state, projection };
    }
    default:
      return state;
  }
}

/** The state of one view, and its one writer. */
export class Store {
  /**
   * @param {StageState} initial
   * @param {(next: StageState, previous: StageState, change: StageChange) => void} changed   told after each change
   */
  constructor(initial, changed) {
    /** @type {StageState} */
    this.current = Object.freeze({ ...initial });
    this.changed = changed;
  }

  /** The state now (frozen: a copy changes, never the state). */
  get state() {
    return this.current;
  }

  /**
   * Applies `change`; tells the owner the next state and the one before. Returns whether anything changed.
   * @param {StageChange} change
   */
  dispatch(change) {
    const previous = this.current;
    const next = reduce(previous, change);
    if (next === previous) return false;
    this.current = Object.freeze(next);
    this.changed(this.current, previous, change);
    return true;
  }
}
