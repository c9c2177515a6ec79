// The core's catalogue for the page (src/catalogue/): the analytic surfaces and congruences as
// menu choices with their default ranges (read from the core once it has started), and every
// entry as formula texts (pkg/catalogue.js, written from the core at build time), which are the
// presets of the formula scenes and the focal scene's congruences — one source of truth.
import { AnalyticSurface, AnalyticCongruence } from '../pkg/ruledlab.js';
import { SURFACE_PRESETS, CONGRUENCE_PRESETS } from '../pkg/catalogue.js';

export { SURFACE_PRESETS, CONGRUENCE_PRESETS };

/** @type {Array<{name: string, title: string, uMin: number, uMax: number, vMin: number, vMax: number, closed: boolean}> | null} */
let surfaces = null;

/** The built-in analytic surfaces (read from the core once, after it has started). */
export function surfaceList() {
  surfaces ??= AnalyticSurface.list();
  return surfaces;
}

/** The built-in surface named `name` (its default ranges). */
export function surfaceInfo(/** @type {string} */ name) {
  const info = surfaceList().find((s) => s.name === name);
  if (!info) throw new Error(`unknown surface "${name}"`);
  return info;
}

/** Menu choices of the surfaces `names` (default: all): [value, i18n key]. */
export function surfaceOptions(/** @type {string[] | null} */ names = null) {
  return () =>
    (names ?? surfaceList().map((s) => s.name)).map((n) => /** @type {[string, string]} */ ([n, `surface.${n}`]));
}

/** Menu choices of the built-in congruences. */
export function congruenceOptions() {
  return AnalyticCongruence.list().map((c) => /** @type {[string, string]} */ ([c.name, `congruence.${c.name}`]));
}

/** Sampling options of a surface: its defaults, overridden by `ranges`. */
export function rangesOf(/** @type {string} */ name, /** @type {object} */ ranges = {}) {
  const { uMin, uMax, vMin, vMax, closed } = surfaceInfo(name);
  return { uMin, uMax, vMin, vMax, closed, ...ranges };
}

/** The catalogue's surface `name` as formulas, or undefined. */
export function surfacePreset(/** @type {string} */ name) {
  return SURFACE_PRESETS.find((p) => p.name === name);
}

/** The catalogue's congruence `name` as formulas, or undefined. */
export function congruencePreset(/** @type {string} */ name) {
  return CONGRUENCE_PRESETS.find((p) => p.name === name);
}

/**
 * The slider of the formula parameter `key` (a, b or c) of the formula scenes: −3 … 3, playable.
 * @param {'a' | 'b' | 'c'} key
 * @param {number} value
 * @returns {import('./scene.js').Param}
 */
export function formulaParameter(key, value) {
  return {
    key,
    label: `formula.param.${key}`,
    type: 'range',
    min: -3,
    max: 3,
    step: 0.01,
    value,
    exact: true,
    play: true,
  };
}

/**
 * The formula fields of "Your surface" a catalogue surface fills in (its texts from the core), its
 * u and v ranges, whether it is closed, and a, b, c; {} for a name the catalogue does not have.
 * @param {string} name
 * @returns {import('./scene.js').Params}
 */
export function surfaceFields(name) {
  const p = surfacePreset(name);
  if (!p) return {};
  const [[ax, ay, az], [ex, ey, ez]] = [p.a, p.e];
  return {
    ax,
    ay,
    az,
    ex,
    ey,
    ez,
    umin: p.u[0],
    umax: p.u[1],
    vmin: p.v[0],
    vmax: p.v[1],
    closed: p.closed,
    a: p.parameters.a,
    b: p.parameters.b,
    c: p.parameters.c,
  };
}

/**
 * The formula fields of "Your congruence" a catalogue congruence fills in, its u and v ranges, its
 * grid and a, b, c; {} for a name the catalogue does not have.
 * @param {string} name
 * @returns {import('./scene.js').Params}
 */
export function congruenceFields(name) {
  const c = congruencePreset(name);
  if (!c) return {};
  const [[px, py, pz], [ex, ey, ez]] = [c.p, c.e];
  return {
    px,
    py,
    pz,
    ex,
    ey,
    ez,
    umin: c.u[0],
    umax: c.u[1],
    vmin: c.v[0],
    vmax: c.v[1],
    rows: c.rows,
    cols: c.cols,
    a: c.parameters.a,
    b: c.parameters.b,
    c: c.parameters.c,
  };
}

/**
 * The form field (or fields) of a formula scene that an option the core names in an error stands
 * for: `point` is the point formula's letter ("a" for a surface's directrix, "p" for a
 * congruence's point), the direction is e; the ranges u and v; the formula parameters a, b, c
 * of a surface's `parameters`, a congruence's grid `rows` and `cols`.
 * @param {'a' | 'p'} point
 * @returns {(option: string) => string | string[] | null}
 */
export function formulaFieldOf(point) {
  /** @type {Record<string, string | string[]>} */
  const fields = {
    u: ['umin', 'umax'],
    v: ['vmin', 'vmax'],
    e: ['ex', 'ey', 'ez'],
    ...(point === 'a' ? { parameters: 'a' } : { rows: 'rows', cols: 'cols' }),
  };
  for (const [letter, keys] of [
    [point, ['x', 'y', 'z'].map((c) => `${point}${c}`)],
    ['e', ['ex', 'ey', 'ez']],
    ['u', ['umin', 'umax']],
    ['v', ['vmin', 'vmax']],
  ])
    for (const [k, key] of /** @type {string[]} */ (keys).entries()) fields[`${letter}[${k}]`] = key;
  return (option) => fields[option] ?? null;
}
