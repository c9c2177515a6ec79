// The line marked in both views while the Klein view stands beside the 3D view: hovering a line
// (the pointer within a few pixels of it, in either view) or tapping it marks it — bold in
// space here, a ring around its point on M in the Klein view (stage/klein-pane.js). One state
// field (`marked`, a line of what the scene exports) holds it; the part asks for it through
// `mark`, and draws from the state and what the core built.
import { toScreen } from '../edit/geometry.js';
import { pickLines, nearestSegment } from '../ui/pick-lines.js';
import { multiply } from '../math.js';
import { MAX_KLEIN_LINES } from '../limits.js';

const SVG = 'http://www.w3.org/2000/svg';

/** The marked line in the 3D view: a bold stroke over it, placed after each frame. */
export class LineMark {
  /**
   * @param {import('./elements.js').StageElements} els
   * @param {{viewer: import('../viewer.js').Viewer, mark: (line: number | null) => void}} ports
   */
  constructor(els, ports) {
    this.els = els;
    this.ports = ports;
    const doc = els.view.ownerDocument;
    this.svg = doc.createElementNS(SVG, 'svg');
    this.svg.classList.add('rl-line-mark');
    this.svg.setAttribute('aria-hidden', 'true');
    this.line = doc.createElementNS(SVG, 'line');
    this.svg.append(this.line);
    this.svg.toggleAttribute('hidden', true);
    els.labels.before(this.svg);
    /** @type {Float64Array | null} the lines of the scene (6 numbers each), while the Klein view is shown */
    this.segments = null;
    /** @type {Float32Array | null} */
    this.transform = null;
    /** @type {number | null} */
    this.marked = null;
    /** @type {Float32Array | null} the view's last projection */
    this.viewProj = null;
    ports.viewer.overlays.push((m) => this.place(m));
    pickLines(
      els.canvas,
      (x, y) => this.nearest(x, y),
      (line) => this.segments && ports.mark(line),
    );
  }

  /**
   * Draws the state's marked line of `built`'s lines (none unless the Klein view is shown).
   * @param {import('../store.js').StageState} state
   * @param {import('../scene.js').Built | null} built
   */
  render(state, built) {
    // (the lines the Klein view draws: none beyond its limit)
    const data = state.view === 'split' ? built?.data : null;
    const segments = data && data.segments.length / 6 <= MAX_KLEIN_LINES ? data.segments : null;
    this.segments = segments;
    /** @type {Float32Array | null} where the 3D view moves them */
    this.transform = segments ? (data?.transform ?? null) : null;
    this.marked = segments && state.marked !== null && state.marked < segments.length / 6 ? state.marked : null;
    if (this.viewProj) this.place(this.viewProj);
    else this.svg.toggleAttribute('hidden', true);
  }

  /** @internal Places the stroke for the projection of the frame just drawn. @param {Float32Array} viewProj */
  place(viewProj) {
    this.viewProj = viewProj;
    const i = this.marked;
    if (i === null || !this.segments) {
      this.svg.toggleAttribute('hidden', true);
      return;
    }
    const { clientWidth: w, clientHeight: h } = this.els.canvas;
    const s = this.segments;
    const m = this.transform ? multiply(viewProj, this.transform) : viewProj;
    const a = toScreen(m, [s[6 * i], s[6 * i + 1], s[6 * i + 2]], w, h);
    const b = toScreen(m, [s[6 * i + 3], s[6 * i + 4], s[6 * i + 5]], w, h);
    this.svg.toggleAttribute('hidden', !a.visible || !b.visible);
    this.svg.setAttribute('width', String(w));
    this.svg.setAttribute('height', String(h));
    for (const [k, v] of Object.entries({ x1: a.x, y1: a.y, x2: b.x, y2: b.y })) this.line.setAttribute(k, String(v));
  }

  /** @internal The line drawn nearest to (x, y), or −1. @param {number} x @param {number} y */
  nearest(x, y) {
    if (!this.segments || !this.viewProj) return -1;
    const { clientWidth: w, clientHeight: h } = this.els.canvas;
    const m = this.transform ? multiply(this.viewProj, this.transform) : this.viewProj;
    return nearestSegment(this.segments, m, w, h, x, y);
  }
}
