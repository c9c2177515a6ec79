// Where a dragged handle goes: the page finds, on screen, the targets near the pointer — other
// handles, the lines of the handle sets (rulings, lines of a grid, tool axes), and what a scene
// declares (footpoints, the striction points, an axis, a plane) — and the core decides the place
// exactly (snapPoint: the handle on its constraint, and snapped onto each target). A snap is
// taken when the core's point is within a few CSS pixels of the pointer (more on a finger);
// points before lines before planes. The constraint is the drag's mode (facing the viewer, along
// the handle's own line, along the input's z-axis) unless the scene or the exercise holds the
// handle (on a line, on a plane, fixed). Everything here is the camera's geometry; the
// incidences are the core's.
import { snapPoint } from '../../pkg/ruledlab.js';
import { pointerRay, toScreen, transformPoint } from './geometry.js';
import { normalize, sub } from '../math.js';
import { plainRich } from '../ui/richtext.js';

/**
 * A target on screen: what the core is asked about, and what a snap onto it is called.
 * @typedef {object} Candidate
 * @property {'point' | 'line' | 'plane'} kind
 * @property {number[]} point        input coordinates
 * @property {number[]} [direction]  a line: b − a
 * @property {number[]} [normal]     a plane
 * @property {string} name           in words ("ruling 5", "footpoint f₃,₄")
 * @property {number} rank           among targets of a kind within reach, the lower first (the
 *   neighbouring rulings before the others)
 * @property {number} distance       from the pointer on screen (CSS px; planes 0)
 */

/**
 * A constraint of the drag, in input coordinates (the core's `SnapConstraint`).
 * @typedef {{kind: 'view', normal: number[]} | {kind: 'line', point: number[], direction: number[]} | {kind: 'plane', point: number[], normal: number[]} | {kind: 'fixed', point: number[]}} DragConstraint
 */

/**
 * Where the pointer puts the handle.
 * @typedef {object} Placed
 * @property {number[] | null} point   input coordinates; null: the handle stays (`held` says why)
 * @property {number[] | null} free    where it would be without snapping
 * @property {'degenerate' | 'parallel' | 'outside' | null} held
 * @property {{name: string, kind: string, world: number[]} | null} snap   what it was snapped onto
 */

/** The direction of a rigid transform's linear part applied to `v` (no translation). */
function turn(/** @type {ArrayLike<number> | null | undefined} */ m, /** @type {number[]} */ v) {
  if (!m) return v;
  return [0, 1, 2].map((k) => m[k] * v[0] + m[4 + k] * v[1] + m[8 + k] * v[2]);
}

/** Distance (CSS px) from (x, y) to the screen segment p q. */
function toSegment(
  /** @type {{x: number, y: number}} */ p,
  /** @type {{x: number, y: number}} */ q,
  /** @type {number} */ x,
  /** @type {number} */ y,
) {
  const dx = q.x - p.x,
    dy = q.y - p.y;
  const len2 = dx * dx + dy * dy;
  const s = len2 > 0 ? Math.max(0, Math.min(1, ((x - p.x) * dx + (y - p.y) * dy) / len2)) : 0;
  return Math.hypot(p.x + s * dx - x, p.y + s * dy - y);
}

/**
 * The constraint a drag of `handle` keeps: a held handle's own (scene, exercise), else the mode's.
 * @param {import('./editor.js').Editor} editor
 * @param {import('./editor.js').Handle} handle
 * @param {import('./geometry.js').MoveMode} mode
 * @param {number[]} forward   the view's direction, world coordinates
 * @returns {DragConstraint}
 */
export function constraintOf(editor, handle, mode, forward) {
  const set = editor.sets[handle.set];
  const held = editor.rules.held(handle);
  if (held) return held;
  if (mode === 'line' && set.shape === 'pairs') {
    const other = editor.handles().find((h) => h.set === handle.set && h.index === (handle.index ^ 1));
    if (other) return { kind: 'line', point: handle.point, direction: sub(other.point, handle.point) };
  }
  // the input's own z-axis (a set drawn turned, as the bending scene's, keeps its vertical)
  if (mode === 'vertical') return { kind: 'line', point: handle.point, direction: [0, 0, 1] };
  const inverse = editor.inverseOf(handle.set);
  return { kind: 'view', normal: turn(inverse, forward) };
}

export class Snapper {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    /** @type {Array<Omit<Candidate, 'distance' | 'rank'> & {rank?: number, screen: (m: ArrayLike<number>, w: number, h: number, x: number, y: number) => number}>} */
    this.targets = [];
  }

  /**
   * The targets a drag of handle `k` may snap onto (made once as the drag begins: what moves with
   * the handle — its own line, its other end, what the scene derives from its line — is left out).
   */
  begin(/** @type {number} */ k) {
    const editor = this.editor;
    this.targets = [];
    if (!editor.snapping) return;
    const all = editor.handles();
    const handle = all[k];
    const set = editor.sets[handle.set];
    const m = set.transform;
    const line = set.shape === 'pairs' ? handle.index >> 1 : -1;
    const { t } = editor.hooks.i18n();
    const screenOf =
      (/** @type {number[]} */ p) =>
      (/** @type {ArrayLike<number>} */ v, w = 1, h = 1) =>
        toScreen(v, transformPoint(m, p), w, h);
    // other handles of the same set (not the handle's other end)
    for (const other of all) {
      if (other.set !== handle.set || other.index === handle.index) continue;
      if (line >= 0 && other.index >> 1 === line) continue;
      const at = screenOf(other.point);
      this.targets.push({
        kind: 'point',
        point: other.point,
        name: editor.nameOf(other),
        screen: (v, w, h, x, y) => {
          const s = at(v, w, h);
          return s.visible ? Math.hypot(s.x - x, s.y - y) : Infinity;
        },
      });
    }
    // the lines of the set (rulings, lines of a grid, tool axes), not the handle's own
    if (set.shape === 'pairs')
      for (let i = 0; 6 * i + 5 < set.points.length; i++) {
        if (i === line) continue;
        const a = all.find((h) => h.set === handle.set && h.index === 2 * i);
        const b = all.find((h) => h.set === handle.set && h.index === 2 * i + 1);
        if (!a || !b) continue;
        // the neighbouring lines (a pair of consecutive rulings) come first
        const neighbour = Math.abs(i - line) === 1 || (set.closed && Math.abs(i - line) === set.points.length / 6 - 1);
        this.pushLine(a.point, b.point, m, this.lineName(set, i, t), neighbour ? 0 : 1);
      }
    // what the scene declares, unless it moves with the handle's line
    for (const group of set.targets ?? []) {
      const stride = group.kind === 'point' ? 3 : 6;
      for (let i = 0; stride * i + stride - 1 < group.points.length; i++) {
        if (line >= 0 && group.of?.(i).includes(line)) continue;
        const p = Array.from(group.points.subarray(stride * i, stride * i + 3));
        const name = t(group.name, { i: String(i), ...(group.vars?.(i) ?? {}) });
        if (group.kind === 'point') {
          const at = screenOf(p);
          this.targets.push({
            kind: 'point',
            point: p,
            name,
            screen: (v, w, h, x, y) => {
              const s = at(v, w, h);
              return s.visible ? Math.hypot(s.x - x, s.y - y) : Infinity;
            },
          });
        } else if (group.kind === 'line') {
          this.pushLine(p, Array.from(group.points.subarray(6 * i + 3, 6 * i + 6)), m, name);
        } else {
          const normal = Array.from(group.points.subarray(6 * i + 3, 6 * i + 6));
          this.targets.push({ kind: 'plane', point: p, normal, name, screen: () => 0 });
        }
      }
    }
  }

  /** @internal A line through the input points a and b (drawn from a to b) as a target. */
  pushLine(
    /** @type {number[]} */ a,
    /** @type {number[]} */ b,
    /** @type {ArrayLike<number> | undefined} */ m,
    /** @type {string} */ name,
    rank = 1,
  ) {
    const [wa, wb] = [transformPoint(m, a), transformPoint(m, b)];
    this.targets.push({
      kind: 'line',
      rank,
      point: a,
      direction: sub(b, a),
      name,
      screen: (v, w, h, x, y) => {
        const [p, q] = [toScreen(v, wa, w, h), toScreen(v, wb, w, h)];
        return p.visible && q.visible ? toSegment(p, q, x, y) : Infinity;
      },
    });
  }

  /** The name of line `i` of a set of pairs, as a target ("ruling 5", "line (1, 2)", "axis of pose 3"). */
  lineName(
    /** @type {import('../scene.js').HandleSet} */ set,
    /** @type {number} */ i,
    /** @type {(key: string, vars?: Record<string, string>) => string} */ t,
  ) {
    /** @type {Record<string, string>} */
    const vars = { i: String(i) };
    if (set.cols) Object.assign(vars, { row: String(Math.floor(i / set.cols)), col: String(i % set.cols) });
    return t(set.lineName ?? 'snap.line', vars);
  }

  /**
   * Where the pointer at (x, y) (CSS px of the view; the handle's intended place on screen) puts
   * handle `handle` that was at `start` (input coordinates) when the drag began, under
   * `constraint`; snapped within `reach` CSS px.
   * @param {import('./editor.js').Handle} handle
   * @param {number[]} start
   * @param {DragConstraint} constraint
   * @param {number} x @param {number} y @param {number} reach
   * @returns {Placed}
   */
  place(handle, start, constraint, x, y, reach) {
    const editor = this.editor;
    const { camera, canvas } = editor.viewer;
    const r = canvas.getBoundingClientRect();
    const w = r.width || 1,
      h = r.height || 1;
    const world = pointerRay(camera, x, y, w, h);
    const inverse = editor.inverseOf(handle.set);
    const ray = {
      origin: inverse ? transformPoint(inverse, world.origin) : world.origin,
      direction: turn(inverse, world.dir),
    };
    const v = camera.viewProj(w / h);
    /** @type {Candidate[]} */
    const near = [];
    for (const target of this.targets) {
      const distance = target.screen(v, w, h, x, y);
      if (distance <= reach * 1.5) near.push({ ...target, rank: target.rank ?? 1, distance });
    }
    near.sort((a, b) => a.distance - b.distance);
    const candidates = near.slice(0, 16);
    const box = /** @type {{min: number[], max: number[]}} */ (
      editor.box ?? { min: [-1e9, -1e9, -1e9], max: [1e9, 1e9, 1e9] }
    );
    const placed = snapPoint({
      ray: { origin: triple(ray.origin), direction: triple(ray.direction) },
      start: triple(start),
      constraint: coreConstraint(constraint),
      targets: candidates.map((c) =>
        c.kind === 'point'
          ? { kind: 'point', point: triple(c.point) }
          : c.kind === 'line'
            ? { kind: 'line', point: triple(c.point), direction: triple(/** @type {number[]} */ (c.direction)) }
            : { kind: 'plane', point: triple(c.point), normal: triple(/** @type {number[]} */ (c.normal)) },
      ),
      bounds: { min: triple(box.min), max: triple(box.max) },
    });
    const free = placed.point ? Array.from(placed.point) : null;
    const m = editor.sets[handle.set].transform;
    /** @type {Placed['snap']} */
    let snap = null;
    let point = free;
    // a world length of one CSS pixel at the handle's depth: planes are taken within `reach` of them
    const pixel = free ? (2 * pixelAt(camera, transformPoint(m, free))) / h : 0;
    // of the snaps within reach: points before lines before planes, then by rank and distance
    const order = { point: 0, line: 1, plane: 2 };
    const taken = candidates
      .map((c, i) => ({ c, s: placed.snaps[i] }))
      .filter(({ c, s }) => {
        if (!s) return false;
        const screen = toScreen(v, transformPoint(m, Array.from(s)), w, h);
        return c.kind === 'plane'
          ? !!free && Math.hypot(...sub(Array.from(s), free)) <= reach * pixel
          : screen.visible && Math.hypot(screen.x - x, screen.y - y) <= reach;
      })
      .sort((a, b) => order[a.c.kind] - order[b.c.kind] || a.c.rank - b.c.rank || a.c.distance - b.c.distance)[0];
    if (taken?.s) {
      point = Array.from(taken.s);
      snap = { name: plainRich(taken.c.name), kind: taken.c.kind, world: transformPoint(m, point) };
    }
    return { point, free, held: placed.held ?? null, snap };
  }
}

/** A drag's constraint as the core takes it (three numbers per point and vector). */
export function coreConstraint(/** @type {DragConstraint} */ c) {
  /** @type {import('../../pkg/ruledlab.js').SnapConstraint} */
  const out =
    c.kind === 'view'
      ? { kind: 'view', normal: triple(c.normal) }
      : c.kind === 'line'
        ? { kind: 'line', point: triple(c.point), direction: triple(c.direction) }
        : c.kind === 'plane'
          ? { kind: 'plane', point: triple(c.point), normal: triple(c.normal) }
          : { kind: 'fixed', point: triple(c.point) };
  return out;
}

/** Three numbers of a point (the core refuses anything else; a NaN stays a NaN it handles). */
export function triple(/** @type {ArrayLike<number>} */ p) {
  return /** @type {[number, number, number]} */ ([Number(p[0]), Number(p[1]), Number(p[2])]);
}

/** Half the height the view spans at the depth of world point `p` (world units). */
function pixelAt(/** @type {{eye: number[], target: number[], fovY: number}} */ camera, /** @type {number[]} */ p) {
  const forward = normalize(sub(camera.target, camera.eye));
  const d = sub(p, camera.eye);
  const depth = Math.abs(d[0] * forward[0] + d[1] * forward[1] + d[2] * forward[2]);
  return depth * Math.tan(camera.fovY / 2);
}
