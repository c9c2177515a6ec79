// Choosing by pointing, in a scene that offers it (Built.pick): a click or a tap on one of its
// points, or on one of its lines, sets the scene's parameter to that one's index — the Klein
// scene's marked ruling, by its point on M or by its line in space. A press on a handle keeps
// the handle (the edit takes it first and stops the press: edit/pointer.js); a drag turns the
// camera and chooses nothing. The part draws nothing: it asks for the parameter through `set`.
import { nearestPoint, nearestSegment, onTap } from '../ui/pick-lines.js';
import { multiply } from '../math.js';

export class ScenePick {
  /**
   * @param {import('./elements.js').StageElements} els
   * @param {{viewer: import('../viewer.js').Viewer, set: (key: string, value: number) => void}} ports
   */
  constructor(els, ports) {
    this.els = els;
    /** @type {import('../scene.js').Built['pick'] | null} what the scene shown offers */
    this.offer = null;
    /** @type {Float32Array | null} the view's last projection */
    this.viewProj = null;
    ports.viewer.overlays.push((m) => {
      this.viewProj = m;
    });
    onTap(els.canvas, (x, y) => {
      const i = this.nearest(x, y);
      if (i >= 0 && this.offer) ports.set(this.offer.param, i);
    });
  }

  /** What the scene built offers to choose by pointing. @param {import('../scene.js').Built | null} built */
  render(built) {
    this.offer = built?.pick ?? null;
  }

  /** @internal The point or line drawn nearest to (x, y) (points first), or −1. @param {number} x @param {number} y */
  nearest(x, y) {
    const offer = this.offer;
    if (!offer || !this.viewProj) return -1;
    const { clientWidth: w, clientHeight: h } = this.els.canvas;
    const point = offer.points ? nearestPoint(offer.points, this.viewProj, w, h, x, y) : -1;
    if (point >= 0 || !offer.lines) return point;
    const m = offer.transform ? multiply(this.viewProj, offer.transform) : this.viewProj;
    return nearestSegment(offer.lines, m, w, h, x, y);
  }
}
