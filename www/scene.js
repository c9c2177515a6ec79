// The scene contract: what a scene declares and what its create() returns. The page
// (app.js), the <ruled-view> element and the one-file build read only these fields; nothing
// of parsing, legends, wasm start-up or hash handling exists twice.
import { MAX_TEXT_PARAM } from './limits.js';

/**
 * A parameter of a scene: one control, one key in the link.
 * @typedef {object} Param
 * @property {string} key           its key in the URL hash and in `params`; unique in the scene
 *                                  and never one of RESERVED_KEYS
 * @property {'range' | 'select' | 'checkbox' | 'text'} type
 * @property {string} label         i18n key of its label
 * @property {number | string | boolean} value   the default
 * @property {number} [min]          range: least value
 * @property {number} [max]          range: greatest value
 * @property {number} [step]         range: slider step
 * @property {boolean} [exact]       range: a field beside the slider takes exact values ("1/13")
 * @property {boolean} [play]        range: can be played (animated) by the player
 * @property {() => Array<[string, string]>} [options]  select: [value, i18n key of its title]
 * @property {number} [maxLength]    text: longest value (default MAX_TEXT_PARAM of limits.js)
 * @property {boolean} [refit]       select: whether a change reframes the camera (default true)
 * @property {(params: Params) => string} [unit]   range: i18n key of the unit its value is in
 *   (shown after the value and said with it), which may follow other parameters
 * @property {(value: number | string | boolean, params: Params) => Params} [sets]
 *   other parameters a choice sets as well (a preset fills the formula fields)
 * @property {(params: Params) => string | null} [unless]
 *   the i18n key of the reason why the control does nothing for these `params` (it is then
 *   disabled, the reason shown), or null when it matters
 *
 * @typedef {Record<string, number | string | boolean>} Params
 *
 * A legend entry: a style of theme.js and what it shows.
 * @typedef {object} LegendEntry
 * @property {string} style          key of STYLES
 * @property {string} label          i18n key; the text may use R_{i,i+1}-style subscripts
 * @property {(params: Params) => boolean} [when]   shown only when true
 *
 * What create() is given besides the parameters.
 * @typedef {object} Context
 * @property {(key: string, vars?: Record<string, string | number>) => string} t
 * @property {(x: number | string | boolean | null | undefined) => string} format
 * @property {string} [lang]         the view's language ("en", "de"): formulas take decimal commas in German
 * @property {ImportedData} [data]   your own segments (the "data" scene)
 * @property {(segments: Float64Array, options: import('../pkg/ruledlab.js').SubdivideOptions, onProgress: (f: number) => void, draw?: number) => Promise<{segments: Float32Array, rulings: number, drawn: number}>} [refine]
 *   refinement in a Web Worker, for large models (at most `draw` rulings come back: every k-th)
 * @property {(job: {segments: Float64Array, closed: boolean, every: number}, onProgress: (f: number) => void) => Promise<{segments: Float32Array, striction: Float32Array, parallel: Uint8Array, parallelPairs: number, leastDelta: number, rulings: number}>} [invariants]
 *   the invariants of many rulings in a Web Worker, reduced to what a level of detail shows
 *   through every `every`-th ruling (invariants-job.js)
 * @property {Input} [input]        the reader's edit of the scene's input (its handles dragged):
 *   the scene computes on it instead of its built-in input, with every tool it has
 *
 * The editable input of a scene: one Float64Array per handle set, by the set's key.
 * @typedef {Record<string, Float64Array>} Input
 *
 * A set of handles: part of a scene's input that the reader can grab and move (by pointer,
 * finger or keyboard). The points are the core's input, copied; a moved handle goes back to the
 * core as the scene's `context.input`.
 * @typedef {object} HandleSet
 * @property {string} key            its name in `Input`, in the link and in <ruled-view>'s `data`
 *   ("rulings", "points", "lines", "poses")
 * @property {Float64Array} points   3 numbers per handle
 * @property {'pairs' | 'points'} shape   pairs: handles 2k and 2k + 1 are the two ends of line k
 *   (a ruling, a line of a congruence, a tool axis), along which Shift moves a handle
 * @property {string} name           i18n key naming one handle; its variables: {i} (the line or
 *   point, from 0 as in the core's messages), {end} (the end's name), {row}, {col} (a grid)
 * @property {[string, string]} [ends]   i18n keys of the two ends' names (pairs)
 * @property {number} [cols]         lines of a grid: line k is (k / cols, k % cols)
 * @property {boolean} [carry]       pairs: moving a line's first handle moves its second one with it
 *   (a tool's tip carries the tool; its axis end alone turns it)
 * @property {Float32Array | Float64Array} [transform]   4 × 4 model matrix, column-major: where
 *   the handles are drawn (the layer's transform); a rigid motion
 * @property {string} [lineName]     pairs: i18n key naming line {i} as a snap target ("ruling {i}")
 * @property {boolean} [closed]      pairs: the last line and the first are neighbours (a closed surface)
 * @property {SnapTargets[]} [targets]   what else a dragged handle of the set snaps onto (its
 *   other handles and, for pairs, the other lines are targets anyway)
 *
 * Points, lines or planes of a figure a dragged handle snaps onto (edit/snap.js; the core puts
 * the handle on them exactly), in the set's input coordinates.
 * @typedef {object} SnapTargets
 * @property {'point' | 'line' | 'plane'} kind
 * @property {Float64Array} points   3 numbers per point; 6 per line (two of its points: the part
 *   drawn); 6 per plane (a point, the normal)
 * @property {string} name           i18n key naming target {i} ("footpoint f_{{i},{j}}")
 * @property {(i: number) => Record<string, string>} [vars]   more variables of its name
 * @property {(i: number) => number[]} [of]   the set's lines target i is made from: a drag of one of
 *   their handles moves it, so it is no target then
 *
 * What a scene offers to edit, beside what it built.
 * @typedef {object} Editable
 * @property {HandleSet[]} sets
 * @property {string} from           what the built-in input is, in words ("the hyperboloid of
 *   Example 1, 36 rulings"): the page says "edited from: …"
 * @property {(set: number, index: number) => Readout[]} [values]   the values of handle `index`
 *   of set `set`'s neighbourhood, shown beside it while it moves (a ruling's end: φ, h, δ of both
 *   pairs of its ruling; a tool pose: its orientation steps and deviation); labels are texts
 *
 * Your own segments, or your tool poses (the milling scene).
 * @typedef {object} ImportedData
 * @property {Float64Array} segments 6 numbers per line (tool poses: the tip, then the unit axis)
 * @property {number} [rows]
 * @property {number} [cols]
 * @property {boolean} [poses]   tool poses, not segments
 * @property {{ radius: number, length: number, end: 'ball' | 'flat' }} [tool]   the tool their file names
 * @property {'mm' | 'inch'} [units]   tool poses: the units of their file
 * @property {number[]} [lines]   tool poses: the line of each in its file (errors name it)
 * @property {Float64Array} [target]   tool poses: your target curve, 3 numbers per point
 *
 * Something to draw: f32 buffers from the core, and a style of theme.js.
 * @typedef {object} Layer
 * @property {'segments' | 'polyline' | 'points' | 'mesh'} kind
 *   segments: 6 floats per segment; polyline: 3 per point, consecutive points joined (NaN
 *   points break it); points: 3 per point; mesh: 3 per vertex with `indices`
 * @property {string} style          key of STYLES
 * @property {Float32Array} positions
 * @property {Uint32Array} [indices] mesh: 3 per triangle
 * @property {Float32Array} [normals] mesh: 3 per vertex (the core's meshNormalsF32); shaded
 *   smoothly by them instead of facet by facet — for facets smaller than a pixel, which
 *   facet shading turns into moiré
 * @property {boolean} [closed]      polyline: join the last point to the first
 * @property {Float32Array | Float64Array} [transform]   4 × 4 model matrix, column-major
 * @property {Layer} [moving]       a lighter stand-in drawn while the camera moves (a level of
 *   detail for layers too heavy to redraw at display rate); the layer itself is drawn again
 *   once the camera rests
 *
 * A label anchored to a 3D point (plain text; `_{…}` marks a subscript).
 * @typedef {object} Label
 * @property {number[]} at
 * @property {string} text
 *
 * One number of the readout.
 * @typedef {object} Readout
 * @property {string} label          i18n key (or text)
 * @property {number | string} value
 * @property {boolean} [exactZero]   say "exact" when the value is 0 (to rounding)
 *
 * What create() returns: everything drawn, said and exported for these parameters.
 * @typedef {object} Built
 * @property {{min: number[], max: number[]}} bounds
 * @property {{yaw?: number, pitch?: number}} [camera]   the direction the scene is best seen from
 * @property {Layer[]} layers
 * @property {Label[]} [labels]
 * @property {Float32Array} [keepClear]   segments (6 floats each) labels must not cover
 * @property {Readout[]} [readouts]
 * @property {string} description    what is shown, in words (for screen readers and the figure caption)
 * @property {() => SVGElement} [diagram]   a plot beside the view (built with the DOM)
 * @property {() => SVGElement} [figure]   deprecated: the earlier name of `diagram`
 * @property {Download[]} [downloads]
 * @property {{segments: Float64Array, grid?: {rows: number, cols: number}, closed?: boolean, transform?: Float32Array, image?: {mix: number, turn: number, unit: number}}} [data]
 *   for export (and for the Klein view beside the 3D view, which draws these lines as points of
 *   M); `closed`: the last line and the first are neighbours (a closed surface: the Klein view
 *   joins their points); `transform`: the 4 × 4 model matrix (column-major) the 3D view draws them with, where it
 *   moves them (a line marked in both views is drawn there); `image`: the scene's own Klein image
 *   (the Klein scene's), which the view beside draws in until the reader steers it
 * @property {(image: {mix: number, turn: number, unit: number}) => {layers: Layer[], legend: Array<{style: string, label: string}>, description: string}} [klein]
 *   what the Klein view beside the 3D view draws besides the points of `data`'s lines, in the
 *   image it draws in: e.g. the line-space scheme's points before N
 * @property {{param: string, points?: Float32Array, lines?: Float32Array, transform?: Float32Array}} [pick]
 *   what a click or a tap chooses (stage/scene-pick.js): the one of `points` (3 floats each) or
 *   else of `lines` (6 floats each, drawn moved by `transform`) nearest to it on screen sets
 *   parameter `param` to its index (the Klein scene's marked ruling), which is a line of `data`
 *   too: with the Klein view beside, that line is marked there
 * @property {string} [note]          a remark shown under the readout (e.g. the level of detail)
 * @property {Claim[]} [claims]      the comparative sentences that apply to these parameters,
 *   each checked against the numbers of the readout (tests/node/claims.test.mjs sweeps the
 *   range each claim states and requires it to hold)
 * @property {(onProgress: (fraction: number) => void) => Promise<Built>} [later]   heavy work finishing in a worker
 * @property {Built} [cancelled]   with `later`: the picture to show if that work is cancelled (what
 *   this one says of the work in progress, said of work stopped)
 * @property {Editable} [input]     the handles of the scene's input (its edited input when
 *   `context.input` was given): a scene with handles can be edited by dragging them
 * @property {Record<string, number>} [measures]   named values for exercises' conditions (beside
 *   the numeric readouts, which conditions name by their keys), e.g. "striction.minAbsDelta"
 * @property {string[]} [legendOff]  the labels of legend entries this picture does not draw (a
 *   level of detail without some of the scene's layers): left out of the legend wherever it is shown
 * @property {Record<string, string>} [legendAs]  legend entries this picture draws otherwise: the
 *   label each is shown with instead, by the entry's label
 * @property {string[]} [problems]  what the input's geometry leaves undefined, in words ("rulings
 *   4 and 5 are parallel: δ undefined there"), shown under the readout
 * @property {Record<string, string>} [invalid]   a parameter's value the scene could not use, by its key:
 *   what is wrong, said beside its field (the scene computed with what it uses meanwhile)
 *
 * A comparative sentence of the page, checked against the numbers shown beside it.
 * @typedef {object} Claim
 * @property {string} text           i18n key of the sentence (it states the range it covers)
 * @property {boolean} holds         whether the readout's numbers bear it out here
 *
 * @typedef {object} Download
 * @property {string} label          i18n key
 * @property {string} filename
 * @property {string | Blob | (() => string | Blob | Promise<Blob>)} content   (made when asked for where a function)
 * @property {string} type
 */

/**
 * What a scene is. `P` types its parameters (each scene writes its own, as the values its
 * controls give: a range a number, a checkbox a boolean, a menu or a field a string).
 * @template {Params} [P=Params]
 * @typedef {object} Scene
 * @property {string} id             its name in links and in <ruled-view scene="…">
 * @property {string} title          i18n key
 * @property {string} text           i18n key of its explanation (markup from the project's own files)
 * @property {Param[]} params
 * @property {LegendEntry[]} legend
 * @property {boolean} [paper]       whether the scene reproduces a figure of the paper
 * @property {Array<'cam'>} [needs]  the second wasm module it computes with ('cam': the CAM
 *   module, cam.js), started before the scene opens: create() may then call `cam()`
 * @property {{make(params: P, context: Context): Built}['make']} create
 *   what is drawn, said and exported for these parameters (a method: a scene of typed
 *   parameters is a scene of Params)
 * @property {boolean} [editAsData] the scene has no handles, but its sample can become your data
 *   ("Edit as data": the formula scenes)
 * @property {{exact(params: P, context: Context, kind: 'striction' | 'distribution', samples: number): {u: Float64Array, values: Float64Array} | null}['exact']} [exact]
 *   the exact striction curve s(u) (3 numbers per u) or distribution parameter δ(u) of the
 *   scene's analytic surface at `samples` parameters over its range: what a typed answer is
 *   compared with in an exercise
 * @property {string[]} [fixed]     the parameters an edit of the input replaces (the surface and
 *   the number of its rulings, say): disabled while the input is edited, with the reason
 * @property {(option: string) => string | string[] | null} [fieldOf]
 *   the key of the parameter an error's `details.option` concerns (e.g. a formula "a[1]"), or
 *   the keys it may concern (an interval "u": its two ends; the one the reader changed last is
 *   marked), so the page can mark that field
 */

/** Hash keys the page itself uses: no scene parameter may take them. */
export const RESERVED_KEYS = Object.freeze([
  'scene',
  'cam',
  'embed',
  'controls',
  'text',
  'lang',
  'autoplay',
  'data',
  'note',
  'view',
  'klein',
  'paper',
  'input',
  'edit',
  'task',
  'seed',
  'leave',
  'solution',
]);

/**
 * Checks a scene against the contract (keys unique, none reserved, defaults valid); throws at
 * start-up so that a broken scene never reaches a user.
 * @template {Params} P
 * @param {Scene<P>} scene
 * @returns {Scene<P>}
 */
export function defineScene(scene) {
  const seen = new Set();
  for (const p of scene.params) {
    if (RESERVED_KEYS.includes(p.key))
      throw new Error(`scene ${scene.id}: parameter key "${p.key}" is reserved for the page`);
    if (seen.has(p.key)) throw new Error(`scene ${scene.id}: parameter key "${p.key}" appears twice`);
    seen.add(p.key);
    // (a select's choices may come from the core, which is not started yet: the tests check those)
    if (p.type !== 'select' && readValue(p, serialize(p, p.value)).note)
      throw new Error(`scene ${scene.id}: the default of "${p.key}" is not valid`);
  }
  return scene;
}

/** The string a parameter value takes in a link. */
/**
 * The scheme menu of a scene that refines: a select of key "scheme" that keeps the view where it is.
 * @param {string} value  the scheme chosen at first
 * @param {() => Array<[string, string]>} options  [scheme, i18n key of its title]
 * @param {Partial<Param>} [more]  anything else of the param (e.g. `unless`)
 * @returns {Param}
 */
export function schemeParam(value, options, more = {}) {
  return { key: 'scheme', label: 'param.scheme', type: 'select', value, refit: false, options, ...more };
}

export function serialize(/** @type {Param} */ p, /** @type {number | string | boolean} */ value) {
  if (p.type === 'checkbox') return value ? '1' : '0';
  return String(value);
}

/**
 * Reads a number written as a decimal or a fraction ("0.0769", "1/13", "-1/16").
 * @param {string} text
 * @returns {number} NaN when it is neither
 */
export function parseNumber(text) {
  const t = String(text).trim().replace('−', '-').replace(',', '.');
  const fraction = /^([+-]?\d+(?:\.\d*)?)\s*\/\s*(\d+(?:\.\d*)?)$/.exec(t);
  if (fraction) return Number(fraction[1]) / Number(fraction[2]);
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(t) ? Number(t) : NaN;
}

/**
 * One parameter's value from its link text: the value, or the default with a note saying why.
 * @param {Param} p
 * @param {string | null} raw
 * @returns {{value: number | string | boolean, note?: string}}
 */
export function readValue(p, raw) {
  if (raw === null) return { value: p.value };
  if (p.type === 'checkbox') {
    if (['1', 'true'].includes(raw)) return { value: true };
    if (['0', 'false'].includes(raw)) return { value: false };
    return { value: p.value, note: 'note.notOnOff' };
  }
  if (p.type === 'range') {
    const x = parseNumber(raw);
    if (!Number.isFinite(x)) return { value: p.value, note: 'note.notNumber' };
    const min = /** @type {number} */ (p.min),
      max = /** @type {number} */ (p.max);
    if (x < min || x > max) return { value: Math.min(max, Math.max(min, x)), note: 'note.clamped' };
    return { value: x };
  }
  if (p.type === 'select') {
    const values = (p.options?.() ?? []).map(([v]) => v);
    return values.includes(raw) ? { value: raw } : { value: p.value, note: 'note.unknownChoice' };
  }
  const limit = p.maxLength ?? MAX_TEXT_PARAM;
  return raw.length <= limit ? { value: raw } : { value: p.value, note: 'note.tooLong' };
}

/**
 * Every parameter of `scene` from a query (missing ones take their defaults); values that
 * cannot be used fall back to their defaults, each with a note for the page to show.
 * @param {Scene} scene
 * @param {URLSearchParams} query
 * @returns {{params: Params, notes: Array<{key: string, note: string}>}}
 */
export function readParams(scene, query) {
  /** @type {Params} */
  const params = {};
  const notes = [];
  for (const p of scene.params) {
    const { value, note } = readValue(p, query.get(p.key));
    params[p.key] = value;
    if (note) notes.push({ key: p.key, note });
  }
  return { params, notes };
}

/**
 * The parameters named in `values` (an object, or a query string), read as a link's are: those
 * of `scene` with their values (one that cannot be used falls back as in readParams, with a
 * note), and a note `note.unknownParam` for each name that is not a parameter of `scene`.
 * @param {Scene} scene
 * @param {Record<string, number | string | boolean> | string} values
 * @returns {{params: Params, notes: Array<{key: string, note: string, vars?: Record<string, string>}>}}
 */
export function readSome(scene, values) {
  const entries = typeof values === 'string' ? values : Object.entries(values).map(([k, v]) => [k, String(v)]);
  const query = new URLSearchParams(entries);
  const read = readParams(scene, query);
  const known = scene.params.map((p) => p.key);
  const params = Object.fromEntries(known.filter((k) => query.has(k)).map((k) => [k, read.params[k]]));
  const unknown = [...new Set(query.keys())].filter((k) => !known.includes(k));
  const vars = (/** @type {string} */ key) => ({ key, known: known.join(', ') });
  return {
    params,
    notes: [...read.notes, ...unknown.map((key) => ({ key, note: 'note.unknownParam', vars: vars(key) }))],
  };
}

/**
 * The scene's defaults with `chosen` parameters and what those choices set besides (Param.sets:
 * a preset fills the formula fields), as choosing them in the controls does; values chosen
 * explicitly win over what a choice sets.
 * @param {Scene} scene
 * @param {Params} chosen
 * @returns {Params}
 */
export function withChoices(scene, chosen) {
  let out = { ...defaults(scene), ...chosen };
  for (const p of scene.params)
    if (p.sets && p.key in chosen) out = { ...out, ...p.sets(chosen[p.key], out), ...chosen };
  return out;
}

/** The defaults of every parameter. */
export function defaults(/** @type {Scene} */ scene) {
  return Object.fromEntries(scene.params.map((p) => [p.key, p.value]));
}

/**
 * The reason (i18n key) why `p` does nothing for `params`, or null.
 * @param {Param} p
 * @param {Params} params
 */
export function irrelevance(p, params) {
  return p.unless?.(params) ?? null;
}

/**
 * Runs `body` with an `own` function that registers wasm objects, and frees every one of them
 * afterwards, whether `body` returns or throws. Scenes create their wasm objects through it.
 * @template T
 * @param {(own: <O extends {free(): void}>(object: O) => O) => T} body
 * @returns {T}
 */
export function scoped(body) {
  /** @type {Array<{free(): void}>} */
  const owned = [];
  try {
    return body((object) => {
      owned.push(object);
      return object;
    });
  } finally {
    for (const o of owned.reverse()) o.free();
  }
}

/** Bounding box {min, max} of flat xyz arrays (NaN skipped): math.js's, for scenes. */
export { bounds } from './math.js';

/** A Float32Array copy of any numbers (no copy when already f32). */
export function f32(/** @type {ArrayLike<number>} */ data) {
  return data instanceof Float32Array ? data : new Float32Array(data);
}

/**
 * The diagram a scene built beside the view, if any (`Built.diagram`, or its earlier name
 * `figure` from a scene of one's own written before).
 * @param {Built} built
 * @returns {(() => SVGElement) | undefined}
 */
export function diagramOf(built) {
  return built.diagram ?? built.figure;
}

/**
 * The entries of `scene`'s legend that apply to `params` (an entry's `when` decides) and that
 * `built` draws (its `legendOff`), labelled as `built` draws them (its `legendAs`): what the
 * legend on the page, the printed figures and the PNG show alike.
 * @param {Scene} scene
 * @param {Params} params
 * @param {Built | null} [built]
 * @returns {LegendEntry[]}
 */
export function legendOf(scene, params, built) {
  const off = built?.legendOff ?? [];
  const as = built?.legendAs ?? {};
  return scene.legend
    .filter((entry) => (!entry.when || entry.when(params)) && !off.includes(entry.label))
    .map((entry) => (as[entry.label] ? { ...entry, label: as[entry.label] } : entry));
}
