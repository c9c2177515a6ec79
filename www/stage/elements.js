// The elements of a stage, built once: the view (canvas, labels, legend, the bar with the hint,
// the edit bar and the toolbar, progress, notes, errors, the screen reader's description and
// live region) and the panel beside or below it (heading, exercise, paper card, controls,
// player, readout, figure, downloads, explanation). Nothing here listens or decides: the parts
// of the stage (stage/*.js) fill and wire these elements.
import { KLEIN_RANGES } from '../limits.js';

/**
 * @typedef {object} StageElements
 * @property {HTMLElement} root      the stage (view, panel and the shortcuts dialog)
 * @property {HTMLElement} view      the 3D view's box
 * @property {HTMLCanvasElement} canvas
 * @property {HTMLElement} labels    labels placed by the camera's projection
 * @property {HTMLElement} legend
 * @property {HTMLElement} bar       the view's bottom edge: the hint (or the edit bar) and the toolbar
 * @property {HTMLElement} hint
 * @property {HTMLElement} toolbar
 * @property {HTMLElement} editBar   while editing: how a drag moves a handle, and Done
 * @property {Record<import('../edit/geometry.js').MoveMode, HTMLButtonElement>} modes
 * @property {HTMLElement} modeGroup
 * @property {HTMLElement} modeLabel
 * @property {HTMLButtonElement} snap   snapping on or off
 * @property {HTMLButtonElement} done
 * @property {{edit: HTMLButtonElement, undo: HTMLButtonElement, redo: HTMLButtonElement, klein: HTMLButtonElement, fit: HTMLButtonElement, reset: HTMLButtonElement, fullscreen: HTMLButtonElement, help: HTMLButtonElement}} buttons
 * @property {HTMLElement} progress
 * @property {HTMLProgressElement} progressBar
 * @property {HTMLButtonElement} cancel
 * @property {HTMLElement} error     an error over the view (role alert)
 * @property {HTMLElement} noteBox   notes about link values that were not used
 * @property {HTMLElement} description   what the figure shows, for screen readers
 * @property {HTMLElement} status    the polite live region
 * @property {HTMLElement} klein     the Klein view's box beside the 3D view (its canvas comes and goes: stage/klein-pane.js)
 * @property {HTMLElement} kleinLabels
 * @property {HTMLElement} kleinLegend   in the Klein view's box, or in the panel under the view's legend
 * @property {HTMLElement} kleinNote     why the Klein view shows nothing
 * @property {HTMLElement} kleinDescription   what the Klein view shows, for screen readers
 * @property {HTMLDetailsElement} kleinSteer   the Klein view's sliders α, β, ℓ (its image of P⁵), in its
 *   corner, or in the panel under its legend; folded under its summary in a narrow box without a
 *   panel (stage/layout.js)
 * @property {HTMLElement} kleinSteerSummary
 * @property {Record<'mix' | 'turn' | 'unit', {input: HTMLInputElement, name: HTMLElement, value: HTMLOutputElement}>} kleinSliders
 * @property {HTMLElement} panel
 * @property {HTMLElement} heading
 * @property {HTMLElement} authorBox the place of the page's "Make an exercise" panel
 * @property {HTMLElement} taskBox   the exercise: prompt, answers, Check, hints
 * @property {HTMLElement} paperCard the paper's figure shown, and the way back to it
 * @property {HTMLElement} edited    "edited from: …", with the way back to the built-in input
 * @property {HTMLElement} coords    the chosen point: its coordinates (typed) and values
 * @property {HTMLElement} form      the controls
 * @property {HTMLButtonElement} asData   "Edit as data" of a scene without handles
 * @property {HTMLElement} player    speed and single step
 * @property {HTMLElement} readout
 * @property {HTMLElement} problems  what an edited input leaves undefined
 * @property {HTMLElement} claims
 * @property {HTMLElement} note      the readout's note
 * @property {HTMLElement} caption
 * @property {HTMLElement} diagram   a picture beside the view (a plot, a stencil)
 * @property {HTMLElement} downloads
 * @property {HTMLElement} text      the scene's explanation
 * @property {HTMLDialogElement} shortcuts
 */

let serial = 0;

/**
 * Builds a stage's elements into `host`.
 * @param {HTMLElement} host
 * @param {{page?: boolean}} options   page: the page's stage (the page scrolls)
 * @returns {StageElements}
 */
export function stageElements(host, { page = false }) {
  const id = `rl-stage-${++serial}`;
  const doc = host.ownerDocument;
  /** @template {keyof HTMLElementTagNameMap} K @param {K} tag @param {Record<string, any>} [props] @returns {HTMLElementTagNameMap[K]} */
  const el = (tag, props = {}) => Object.assign(doc.createElement(tag), props);
  const button = (/** @type {string} */ className = '', hidden = false) =>
    el('button', { type: 'button', className, hidden });
  // the page's shell (in the HTML of the production page and the one-file build): its stage, view,
  // panel and heading, painted before any script ran, are taken over where they are
  const shell = /** @type {HTMLElement | null} */ (host.querySelector(':scope > .rl-stage'));
  const take = (/** @type {string} */ selector) =>
    /** @type {HTMLElement | null} */ (shell?.querySelector(`:scope > ${selector}`) ?? null);

  const canvas = el('canvas', { tabIndex: 0 });
  // an application: a screen reader in browse mode passes the view's keys (arrows, letters) to
  // it once it has focus, which it would take for its own navigation over an image
  canvas.setAttribute('role', 'application');
  const labels = el('div', { className: 'rl-labels' });
  labels.setAttribute('aria-hidden', 'true');
  const progressBar = el('progress', { max: 1, value: 0 });
  const cancel = button();
  const progress = el('div', { className: 'rl-progress', hidden: true });
  progress.append(progressBar, cancel);
  const error = el('p', { className: 'rl-error', hidden: true });
  error.setAttribute('role', 'alert');
  const description = el('p', { className: 'rl-sr-only', id: `${id}-description` });
  canvas.setAttribute('aria-describedby', description.id);
  const status = el('p', { className: 'rl-sr-only' });
  status.setAttribute('aria-live', 'polite');

  // while editing (in the hint's place): how a drag moves a handle (for those without Shift and Alt), and Done
  const modes = { view: button('rl-mode-view'), line: button('rl-mode-line'), vertical: button('rl-mode-vertical') };
  const modeLabel = el('span', { className: 'rl-editbar-label' });
  const modeGroup = el('div', { className: 'rl-modes' });
  modeGroup.setAttribute('role', 'group');
  modeGroup.append(modeLabel, ...Object.values(modes));
  const snap = button('rl-snap');
  const done = button('rl-done');
  const editBar = el('div', { className: 'rl-editbar', hidden: true });
  editBar.append(modeGroup, snap, done);
  const buttons = {
    edit: button('rl-edit', true),
    undo: button('rl-undo', true),
    redo: button('rl-redo', true),
    klein: button('rl-klein-toggle'),
    fit: button('rl-fit'),
    reset: button('rl-reset'),
    fullscreen: button('rl-fullscreen'),
    help: button('rl-help'),
  };
  const toolbar = el('div', { className: 'rl-toolbar' });
  toolbar.append(...Object.values(buttons));
  // the hint and the toolbar share the bottom edge: the hint takes what room the buttons leave
  const hint = el('p', { className: 'rl-hint' });
  const bar = el('div', { className: 'rl-bar' });
  bar.append(hint, editBar, toolbar);
  const legend = el('ul', { className: 'rl-legend' });
  const noteBox = el('p', { className: 'rl-note', hidden: true });
  const view = take('.rl-view') ?? el('div', { className: 'rl-view' });
  // the Klein view beside the 3D view (hidden unless asked for)
  const klein = el('section', { className: 'rl-klein', hidden: true });
  const kleinLabels = el('div', { className: 'rl-labels' });
  kleinLabels.setAttribute('aria-hidden', 'true');
  const kleinLegend = el('ul', { className: 'rl-legend rl-klein-legend', hidden: true });
  const kleinNote = el('p', { className: 'rl-klein-note', hidden: true });
  const kleinDescription = el('p', { className: 'rl-sr-only', id: `${id}-klein` });
  const kleinSteer = el('details', { className: 'rl-klein-steer', hidden: true, open: true });
  const kleinSteerSummary = el('summary', { className: 'rl-klein-steer-summary' });
  const kleinSteerGrid = el('div', { className: 'rl-klein-steer-grid' });
  kleinSteerGrid.setAttribute('role', 'group');
  kleinSteer.append(kleinSteerSummary, kleinSteerGrid);
  const kleinSliders = /** @type {StageElements['kleinSliders']} */ ({});
  for (const key of /** @type {const} */ (['mix', 'turn', 'unit'])) {
    const { min, max, step } = KLEIN_RANGES[key];
    const input = el('input', {
      type: 'range',
      min: String(min),
      max: String(max),
      step: String(step),
      id: `${id}-klein-${key}`,
    });
    const name = el('label', { htmlFor: input.id, className: 'rl-klein-name' });
    const value = el('output', { className: 'rl-klein-value' });
    value.htmlFor.add(input.id);
    kleinSliders[key] = { input, name, value };
    kleinSteerGrid.append(name, input, value);
  }
  klein.append(kleinLabels, kleinLegend, kleinSteer, kleinNote, kleinDescription);
  view.append(canvas, klein, labels, legend, bar, progress, noteBox, error, description, status);

  const paperCard = el('section', { className: 'rl-paper', hidden: true, id: `${id}-paper` });
  // a group, not a form: Enter in a field of a form in a sandboxed frame without allow-forms is a
  // blocked submission the console reports (course systems frame the page that way)
  const form = el('div', { className: 'rl-controls' });
  form.setAttribute('role', 'group');
  const parts = {
    heading: take('.rl-panel > h2') ?? el('h2'),
    authorBox: el('section', { className: 'rl-author', hidden: true }),
    taskBox: el('section', { className: 'rl-task', hidden: true }),
    paperCard,
    edited: el('div', { className: 'rl-edited', hidden: true }),
    coords: el('section', { className: 'rl-coords', hidden: true }),
    form,
    asData: button('rl-as-data', true),
    player: el('div', { className: 'rl-player', hidden: true }),
    readout: el('dl', { className: 'rl-readout' }),
    problems: el('ul', { className: 'rl-problems', hidden: true }),
    claims: el('ul', { className: 'rl-claims', hidden: true }),
    note: el('p', { className: 'rl-readout-note', hidden: true }),
    caption: el('p', { className: 'rl-caption' }),
    diagram: el('figure', { className: 'rl-figure' }),
    downloads: el('div', { className: 'rl-downloads' }),
    text: el('article', { className: 'rl-text' }),
  };
  const panel = take('.rl-panel') ?? el('div', { className: 'rl-panel' });
  panel.append(...Object.values(parts).filter((part) => part.parentElement !== panel));

  const shortcuts = el('dialog', { className: 'rl-shortcuts' });
  const root = shell ?? el('div', { className: page ? 'rl-stage rl-page' : 'rl-stage' });
  if (!shell) {
    root.append(view, panel);
    host.append(root);
  }
  root.append(shortcuts);
  return {
    root,
    view,
    canvas,
    labels,
    legend,
    bar,
    hint,
    toolbar,
    editBar,
    modes,
    modeGroup,
    modeLabel,
    snap,
    done,
    buttons,
    progress,
    progressBar,
    cancel,
    error,
    noteBox,
    description,
    status,
    klein,
    kleinLabels,
    kleinLegend,
    kleinNote,
    kleinDescription,
    kleinSteer,
    kleinSteerSummary,
    kleinSliders,
    panel,
    ...parts,
    shortcuts,
  };
}

/**
 * Gives `button` a word, and a sign that stands in for it where the box is narrow (its name
 * stays the word).
 * @param {HTMLElement} button @param {string} sign @param {string} word
 */
export function labelButton(button, sign, word) {
  const doc = button.ownerDocument;
  const icon = Object.assign(doc.createElement('span'), { className: 'rl-btn-sign', textContent: sign });
  icon.setAttribute('aria-hidden', 'true');
  const text = Object.assign(doc.createElement('span'), { className: 'rl-btn-word', textContent: word });
  button.replaceChildren(icon, text);
  button.setAttribute('aria-label', word);
}
