// The link's codec: a view in the URL hash, and back (the page's address, Share's links):
//   #scene=striction&surface=hyperboloid&n=36&cam=yaw,pitch,distance,x,y,z&lang=de&klein=30,90,1
//   (klein: the Klein view beside, in the image α,β,ℓ; a bare klein: in the scene's own image)
// The page's own keys (RESERVED_KEYS of scene.js) never collide with a scene's parameters.
// A hash longer than MAX_HASH characters is not read at all (the page says so); a value that
// cannot be used falls back to its default with a note, never an exception.
import { readParams, serialize } from './scene.js';
import { findPreset, withPreset } from './paper.js';
import { decodeInput, encodeInput, linkableInput } from './edit/input.js';
import { MAX_HASH, MAX_LINK_RULINGS } from './limits.js';
import { append } from './reduce.js';
import { readProjection, writeProjection } from './klein-projection.js';

/**
 * @typedef {object} LinkState
 * @property {import('./scene.js').Scene} scene
 * @property {import('./scene.js').Params} params
 * @property {number[] | null} camera    yaw, pitch, distance, target x, y, z
 * @property {string | null} lang
 * @property {boolean} embed             the view alone (for an iframe)
 * @property {boolean} controls          with #embed: show the controls too
 * @property {boolean} text              with #embed: show the explanation too
 * @property {boolean} autoplay          start playing
 * @property {import('./scene.js').ImportedData | null} data
 * @property {import('./scene.js').Input | null} [input]   the reader's edit of the scene's input
 *   (its handles moved), bit for bit; up to MAX_LINK_HANDLES handles
 * @property {boolean} [edit]           with #embed: the reader may drag the handles
 * @property {string | null} [task]     an exercise: a built-in one's id, or "j." and its JSON (task/format.js)
 * @property {string | null} [seed]     the seed of the exercise's drawn numbers, as the link writes it
 *   (task/format.js's readSeed says whether it is one)
 * @property {boolean} [leave]          with #embed: the reader may leave the exercise
 * @property {string | null} [solution] when the exercise's solution is offered: "never", or after how
 *   many checks that did not solve it (task/solution-rule.js; absent: after a first one)
 * @property {Array<{key: string, note: string, vars?: Record<string, string>}>} notes   values that were not used, and why
 * @property {string | null} [paper]    the figure or example of the paper shown (paper.js), if any
 * @property {'space' | 'split'} [view]  the 3D view alone, or the Klein view of the scene's lines beside it
 * @property {{mix: number, turn: number, unit: number} | null} [projection]   the image the Klein
 *   view beside draws in, as the reader steered it (α, β in degrees, ℓ; null: the scene's own)
 */

/**
 * Reads a hash (with or without "#") against the list of scenes.
 * @param {string} hash
 * @param {import('./scene.js').Scene[]} scenes
 * @returns {LinkState}
 */
export function readLink(hash, scenes) {
  const notes = [];
  let text = String(hash ?? '').replace(/^#/, '');
  if (text.length > MAX_HASH) {
    notes.push({ key: 'link', note: 'note.linkTooLong', vars: { max: String(MAX_HASH / 1024) } });
    text = '';
  }
  let q = new URLSearchParams(text);
  const preset = findPreset(q.get('paper'));
  if (q.has('paper') && !preset) notes.push({ key: 'paper', note: 'note.unknownFigure' });
  const wanted = q.get('scene') ?? preset?.scene ?? null;
  let scene = scenes.find((s) => s.id === wanted);
  if (!scene) {
    if (wanted !== null) notes.push({ key: 'scene', note: 'note.unknownScene' });
    scene = scenes[0];
  }
  // a figure of the paper: its values where the link gives none (a link naming another scene wins)
  const paper = preset && preset.scene === scene.id ? preset : null;
  if (paper) q = withPreset(paper, scene, q);
  const read = readParams(scene, q);
  append(notes, read.notes);
  const camera = readCamera(q.get('cam') ?? '');
  if (q.has('cam') && !camera) notes.push({ key: 'cam', note: 'note.badCamera' });
  const data = q.has('data') ? readData(q.get('data') ?? '') : null;
  if (q.has('data') && !data) notes.push({ key: 'data', note: 'note.badData' });
  const input = q.has('input') ? decodeInput(q.get('input') ?? '') : null;
  if (q.has('input') && !input) notes.push({ key: 'input', note: 'note.badInput' });
  const lang = q.get('lang');
  // the Klein view's image: three numbers, each held in its range (said); anything else is the scene's own (said)
  const image = q.has('klein') ? readProjection(q.get('klein')) : null;
  if (image === undefined) notes.push({ key: 'klein', note: 'note.badKlein' });
  else if (image?.held) notes.push({ key: 'klein', note: 'note.kleinHeld' });
  return {
    scene,
    params: read.params,
    camera,
    lang: lang && /^[a-z]{2}(-[A-Za-z]{2})?$/.test(lang) ? lang : null,
    embed: q.has('embed'),
    controls: q.has('controls'),
    text: q.has('text'),
    autoplay: q.has('autoplay'),
    data,
    input,
    edit: q.has('edit'),
    task: q.get('task'),
    seed: q.get('seed'),
    leave: q.has('leave'),
    solution: q.get('solution'),
    notes,
    paper: paper?.id ?? null,
    view: q.has('klein') ? 'split' : 'space',
    projection: image?.projection ?? null,
  };
}

/**
 * The hash of a state (without "#"); `wholeInput`: the edit even beyond MAX_LINK_HANDLES (the
 * one-file page keeps its own hash, whose length no address bar limits).
 * @param {Omit<LinkState, 'notes'>} state
 */
export function writeLink(state, { wholeInput = false } = {}) {
  const q = new URLSearchParams();
  if (state.embed) q.set('embed', '');
  if (state.embed && state.controls) q.set('controls', '');
  if (state.embed && state.text) q.set('text', '');
  if (state.embed && state.edit) q.set('edit', '');
  if (state.embed && state.leave) q.set('leave', '');
  if (state.task) q.set('task', state.task);
  if (state.task && state.seed) q.set('seed', state.seed);
  if (state.task && state.solution) q.set('solution', state.solution);
  if (state.paper) q.set('paper', state.paper);
  q.set('scene', state.scene.id);
  for (const p of state.scene.params) q.set(p.key, serialize(p, state.params[p.key]));
  if (state.camera) q.set('cam', writeCamera(state.camera));
  if (state.lang) q.set('lang', state.lang);
  if (state.view === 'split') q.set('klein', state.projection ? writeProjection(state.projection) : '');
  if (state.data && linkable(state.data)) q.set('data', writeData(state.data));
  if (state.input && (wholeInput || linkableInput(state.input))) q.set('input', encodeInput(state.input));
  return q.toString().replace(/=(&|$)/g, '$1');
}

/**
 * A camera from its link text "yaw,pitch,distance,x,y,z" (the `cam` value, <ruled-view camera>),
 * or null when it is not that.
 * @param {string} text
 * @returns {number[] | null}
 */
export function readCamera(text) {
  const camera = String(text)
    .split(',')
    .map((x) => (x.trim() === '' ? NaN : Number(x)));
  return camera.length === 6 && camera.every(Number.isFinite) && camera[2] > 0 ? camera : null;
}

/** The link text of a camera (six numbers, six significant digits). */
export function writeCamera(/** @type {number[]} */ camera) {
  return camera.map((x) => Number(x.toPrecision(6))).join(',');
}

/** Whether imported data is small enough for a link. */
export function linkable(/** @type {import('./scene.js').ImportedData} */ data) {
  return (data.segments.length + (data.target?.length ?? 0) / 2) / 6 <= MAX_LINK_RULINGS;
}

/**
 * "rows x cols:" (for a congruence) or "p:" (tool poses; "p radius~length~b|f:" with their
 * tool) then the numbers, comma-separated, at full precision; tool poses with a target curve
 * add "~t:" and its points' numbers.
 */
export function writeData(/** @type {import('./scene.js').ImportedData} */ data) {
  const tool = data.tool ? `${data.tool.radius}~${data.tool.length}~${data.tool.end === 'flat' ? 'f' : 'b'}` : '';
  const shape = data.poses ? `p${tool}:` : data.rows && data.cols ? `${data.rows}x${data.cols}:` : '';
  const target = data.poses && data.target ? `~t:${Array.from(data.target, (x) => String(x)).join(',')}` : '';
  return shape + Array.from(data.segments, (x) => String(x)).join(',') + target;
}

/**
 * Reads `writeData`'s text; null when it is not that.
 * @param {string} text
 * @returns {import('./scene.js').ImportedData | null}
 */
export function readData(text) {
  const poses = /^p(?:([0-9.eE+]+)~([0-9.eE+]+)~([bf]))?:([^~]*)(?:~t:([-+0-9.eE,]*))?$/.exec(text);
  const m = /^(?:(\d{1,4})x(\d{1,4}):)?([-+0-9.eE,]*)$/.exec(poses ? poses[4] : text);
  if (!m || (poses && m[1])) return null;
  const numbers = m[3].split(',').map(Number);
  if (numbers.length % 6 !== 0 || numbers.length / 6 > MAX_LINK_RULINGS || !numbers.every(Number.isFinite)) return null;
  const segments = new Float64Array(numbers);
  if (poses) {
    const [radius, length] = [Number(poses[1]), Number(poses[2])];
    const tool =
      poses[1] && radius > 0 && length > 0 ? { radius, length, end: poses[3] === 'f' ? 'flat' : 'ball' } : null;
    const points = poses[5] ? poses[5].split(',').map(Number) : [];
    if (points.length % 3 !== 0 || !points.every(Number.isFinite)) return null;
    const target = points.length >= 6 ? { target: new Float64Array(points) } : {};
    return tool
      ? { segments, poses: true, tool: /** @type {any} */ (tool), ...target }
      : { segments, poses: true, ...target };
  }
  if (m[1]) {
    const [rows, cols] = [Number(m[1]), Number(m[2])];
    if (rows * cols * 6 !== numbers.length) return null;
    return { segments, rows, cols };
  }
  return { segments };
}
