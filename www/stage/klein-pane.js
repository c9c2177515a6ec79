// The Klein view beside the 3D view (the split view): the lines the scene shows — its rulings,
// its congruence's grid, the tool axes of a milling program, your data — as points of the Klein
// quadric M, in the Klein scene's image (klein-image.js), with its own camera, legend and
// description. It draws from the state (`view`) and what the core built (`data`), and knows no
// other part of the stage. Its WebGL context exists only while it is shown; its other elements
// are the stage's (stage/elements.js), its legend placed with the view's (stage/layout.js).
import { Viewer } from '../viewer.js';
import { kleinImage, GRID_LEGEND, KLEIN_LEGEND } from '../klein-image.js';
import { KLEIN_PROJECTION, PROJECTION_KEYS } from '../klein-projection.js';
import { showEntries } from '../ui/legend.js';
import { MAX_KLEIN_LINES } from '../limits.js';
import { describeError } from '../ui/errors.js';
import { toScreen } from '../edit/geometry.js';
import { pickLines, nearestPoint } from '../ui/pick-lines.js';

/** Where the view's camera looks from at first: the Klein scene's direction. */
const CAMERA = { yaw: -0.5, pitch: 0.35 };

export class KleinPane {
  /**
   * @param {import('./elements.js').StageElements} els
   * @param {{i18n: () => import('../i18n/index.js').Translator, mark: (line: number | null) => void,
   *   steer: (projection: import('../klein-projection.js').KleinProjection, ended: boolean) => void,
   *   say: (text: string) => void, insets: (canvas: HTMLElement) => {top: number, bottom: number}}} ports
   *   mark: asks for a line to be marked in both views; steer: asks for the view's image (a slider
   *   moved, `ended` when it is let go); insets: the shares of a canvas's height that the view's
   *   overlays cover (a fit frames the figure between them)
   */
  constructor(els, ports) {
    this.els = els;
    this.ports = ports;
    this.box = els.klein;
    this.labels = els.kleinLabels;
    this.legend = els.kleinLegend;
    this.note = els.kleinNote;
    this.description = els.kleinDescription;
    /** the ring around the marked line's point */
    this.ring = Object.assign(els.view.ownerDocument.createElement('span'), {
      className: 'rl-klein-ring',
      hidden: true,
    });
    // (in the box, over the canvas that fills it: the label layer is the viewer's to fill)
    this.box.append(this.ring);
    /** @type {Float32Array | null} the image of each line's point, as drawn */
    this.points = null;
    /** what the view shows, said without the mark */
    this.said = '';
    /** @type {number | null} the marked line */
    this.marked = null;
    /** @type {Float32Array | null} the view's last projection */
    this.viewProj = null;
    /** @type {HTMLCanvasElement | null} */
    this.canvas = null;
    /** @type {Viewer | null} */
    this.viewer = null;
    /** The lines drawn last (a new set of lines of the same scene keeps the camera). */
    this.shown = /** @type {{scene: string, count: number} | null} */ (null);
    /** @type {import('../klein-projection.js').KleinProjection} the image drawn in last */
    this.image = KLEIN_PROJECTION;
    // the sliders steer the image: each step asks for it, the last one (let go) says it ended
    for (const key of PROJECTION_KEYS) {
      const { input } = els.kleinSliders[key];
      const steer = (/** @type {boolean} */ ended) =>
        this.ports.steer({ ...this.image, [key]: Number(input.value) }, ended);
      input.addEventListener('input', () => steer(false));
      input.addEventListener('change', () => steer(true));
    }
  }

  /** Whether the pane is shown. */
  get open() {
    return !this.box.hidden;
  }

  /**
   * Draws the state's view: the Klein image of `built`'s lines beside the 3D view, or nothing.
   * @param {import('../store.js').StageState} state
   * @param {import('../scene.js').Built | null} built
   */
  render(state, built) {
    const split = state.view === 'split';
    this.els.root.classList.toggle('rl-split', split);
    this.box.hidden = !split;
    if (!split) {
      this.legend.hidden = true;
      this.els.kleinSteer.hidden = true;
      this.close();
      return;
    }
    const { t } = this.ports.i18n();
    this.box.setAttribute('aria-label', t('klein.pane.label'));
    const data = built?.data;
    const count = data ? data.segments.length / 6 : 0;
    let failure = '';
    if (!built) failure = '';
    else if (!data || count < 2) failure = t('klein.pane.none');
    else if (count > MAX_KLEIN_LINES) failure = t('klein.pane.tooMany', { count, max: MAX_KLEIN_LINES });
    if (!built || failure) {
      // (nothing drawn: no image to steer)
      this.showNote(failure);
      this.els.kleinSteer.hidden = true;
      return;
    }
    // the image: the reader's, or the scene's own (the Klein scene's sliders), or the default
    const image = state.projection ?? data?.image ?? KLEIN_PROJECTION;
    this.showImage(image);
    try {
      const viewer = this.viewerNow(t);
      const grid = data?.grid ?? null;
      const {
        k,
        layers: drawn,
        conic,
      } = kleinImage(/** @type {Float64Array} */ (data?.segments), {
        grid,
        closed: !grid && !!data?.closed,
        ...image,
      });
      // what the scene adds to its lines' points (drawn in the same image)
      const extra = built.klein?.(image);
      const layers = extra ? drawn.concat(extra.layers) : drawn;
      const outer = k.radii[1];
      const steps = k.omega.length;
      const description = t(grid ? 'klein.pane.describeGrid' : 'klein.pane.describe', {
        count,
        rows: grid?.rows ?? 0,
        cols: grid?.cols ?? 0,
        torsal: k.torsalSteps,
        steps,
        least: Math.abs(k.leastOmega),
        residual: k.maxResidual,
        complex: k.complexResidual,
        ...image,
      }).concat(extra ? ` ${extra.description}` : '');
      const same = this.shown?.scene === state.scene?.id;
      viewer.show(
        {
          bounds: { min: [-outer, -outer, -outer], max: [outer, outer, outer] },
          camera: CAMERA,
          layers,
          description,
        },
        { fit: !same },
      );
      this.shown = { scene: state.scene?.id ?? '', count };
      this.points = k.points;
      this.said = description;
      this.showMark(state);
      // the conic where the three lines span one; a net's edges where the lines are a grid
      const as = /** @type {Record<string, string>} */ (grid ? GRID_LEGEND : {});
      const entries = KLEIN_LEGEND.filter((e) => e.style !== 'conic' || conic);
      showEntries(
        this.legend,
        [...entries.map((e) => ({ ...e, label: as[e.label] ?? e.label })), ...(extra?.legend ?? [])],
        t,
      );
      this.note.hidden = true;
      /** @type {HTMLCanvasElement} */ (this.canvas).hidden = false;
    } catch (e) {
      this.showNote(t('klein.pane.failed', { message: describeError(e, this.ports.i18n()) }));
    }
  }

  /**
   * @internal The sliders and their values at `image`, the image drawn in.
   * @param {import('../klein-projection.js').KleinProjection} image
   */
  showImage(image) {
    this.image = image;
    this.els.kleinSteer.hidden = false;
    const { lang } = this.ports.i18n();
    for (const key of PROJECTION_KEYS) {
      const { input, value } = this.els.kleinSliders[key];
      // (not while the reader holds it: the browser's value is the one asked for)
      if (Number(input.value) !== image[key]) input.value = String(image[key]);
      // (the angles with their unit, as the description says them)
      const number = image[key].toLocaleString(lang, { maximumFractionDigits: 2 });
      value.value = key === 'unit' ? number : `${number}°`;
    }
  }

  /**
   * Rings the state's marked line (a line of the scene's, counted from 0), and says which in the
   * description.
   * @param {import('../store.js').StageState} state
   */
  showMark(state) {
    const count = this.points ? this.points.length / 3 : 0;
    const i = state.view === 'split' && state.marked !== null && state.marked < count ? state.marked : null;
    this.marked = i;
    const marked = i === null ? '' : ` ${this.ports.i18n().t('klein.pane.marked', { i, count })}`;
    if (this.points) this.description.textContent = `${this.said}${marked}`;
    if (this.viewProj) this.placeMark(this.viewProj);
  }

  /** @internal Places the ring for the projection of the frame just drawn. @param {Float32Array} viewProj */
  placeMark(viewProj) {
    this.viewProj = viewProj;
    const i = this.marked;
    const canvas = this.canvas;
    if (i === null || !this.points || !canvas) {
      this.ring.hidden = true;
      return;
    }
    const p = this.points;
    const s = toScreen(viewProj, [p[3 * i], p[3 * i + 1], p[3 * i + 2]], canvas.clientWidth, canvas.clientHeight);
    this.ring.hidden = !s.visible;
    this.ring.style.transform = `translate(${s.x}px, ${s.y}px)`;
  }

  /** @internal A note in the pane's place (no lines, too many, an error), or nothing while the scene computes. */
  showNote(/** @type {string} */ text) {
    this.note.textContent = text;
    this.note.hidden = !text;
    this.description.textContent = text;
    this.legend.hidden = true;
    if (this.canvas) this.canvas.hidden = true;
    this.shown = null;
    this.points = null;
    this.ring.hidden = true;
  }

  /**
   * @internal The pane's viewer, made on its first use (a canvas of its own: one whose context
   * was released cannot have another).
   * @param {(key: string) => string} t
   */
  viewerNow(t) {
    if (this.viewer && this.canvas) return this.viewer;
    const canvas = Object.assign(this.box.ownerDocument.createElement('canvas'), { tabIndex: 0 });
    canvas.setAttribute('role', 'application');
    canvas.setAttribute('aria-describedby', this.description.id);
    this.box.prepend(canvas);
    this.canvas = canvas;
    this.viewer = new Viewer(canvas, this.labels);
    this.viewer.insets = () => this.ports.insets(canvas);
    // the frames it has drawn, counted where a test (or a page) can wait for them
    this.viewer.onFrame = (n) => {
      this.box.dataset.frames = String(n);
    };
    this.viewer.overlays.push((m) => this.placeMark(m));
    // a line marked by pointing at its point, or by [ and ] from the keyboard
    pickLines(
      canvas,
      (x, y) =>
        this.points && this.viewProj
          ? nearestPoint(this.points, this.viewProj, canvas.clientWidth, canvas.clientHeight, x, y)
          : -1,
      (line) => this.ports.mark(line),
    );
    canvas.addEventListener('keydown', (e) => {
      const count = this.points ? this.points.length / 3 : 0;
      if ((e.key !== '[' && e.key !== ']') || !count || e.ctrlKey || e.metaKey || e.altKey) return;
      e.preventDefault();
      e.stopPropagation();
      const step = e.key === ']' ? 1 : -1;
      const i = this.marked === null ? (step > 0 ? 0 : count - 1) : (this.marked + step + count) % count;
      this.ports.mark(i);
      this.ports.say(this.ports.i18n().t('klein.pane.marked', { i, count }));
    });
    this.localize(t);
    return this.viewer;
  }

  /** The texts in the stage's language. @param {(key: string, vars?: Record<string, string | number>) => string} t */
  localize(t) {
    this.box.setAttribute('aria-label', t('klein.pane.label'));
    this.canvas?.setAttribute('aria-label', t('klein.pane.canvas'));
    this.canvas?.setAttribute('aria-roledescription', t('view.role'));
    this.legend.setAttribute('aria-label', t('view.legend'));
    this.els.kleinSteer.querySelector('[role=group]')?.setAttribute('aria-label', t('klein.pane.steer'));
    this.els.kleinSteerSummary.textContent = t('klein.pane.steerShort');
    for (const key of PROJECTION_KEYS) {
      const { input, name } = this.els.kleinSliders[key];
      name.textContent = t(`klein.pane.${key}`);
      input.setAttribute('aria-label', t('klein.pane.slider', { name: t(`klein.param.${key}`) }));
    }
  }

  /** Releases the pane's WebGL context (the pane is closed or the stage disposed). */
  close() {
    delete this.box.dataset.frames;
    this.viewer?.dispose();
    this.canvas?.remove();
    this.viewer = null;
    this.canvas = null;
    this.shown = null;
    this.points = null;
    this.viewProj = null;
    this.ring.hidden = true;
  }
}
