// What a stage says about what the core computed: after a computation the legend, the readout,
// the claims, the problems an edit leaves, the description (for screen readers and as the
// caption), the figure beside the view and the downloads; after a failure the error, over the
// view and next to the control it concerns, in the stage's language (the last picture stays);
// and the notes about link values that were not used. An exercise hides what would give its
// answer away. While a point is dragged only what follows the hand is shown each frame (the
// readout, the problems); the rest once the move ends. A new figure's description is said to
// screen readers (politely); D says it again. It draws from the state and what the core built
// (render); what it needs of its stage are its `ports`.
import { showLegend } from '../ui/legend.js';
import { showReadout, showClaims } from '../ui/readout.js';
import { describeError } from '../ui/errors.js';
import { appendRich, plainRich } from '../ui/richtext.js';
import { download } from '../ui/download.js';
import { say } from '../task/format.js';
import { diagramOf } from '../scene.js';

/**
 * What the results ask of their stage.
 * @typedef {object} ResultsPorts
 * @property {import('./elements.js').StageElements} els
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {(text: string) => void} say      said to screen readers now
 * @property {() => void} hush                 an announcement waiting for its second is dropped
 * @property {() => void} refit                the view fitted anew where it is narrow and at home
 *   (the legend may cover another share of it now)
 * @property {(key: string, message: string | null) => void} mark   a control marked invalid (null: not)
 * @property {(error: unknown, message: string) => void} [onError]   the stage's owner told
 */

export class Results {
  /** @param {ResultsPorts} ports */
  constructor(ports) {
    this.ports = ports;
    /** the scene whose description was said last (a new one is said once) */
    this.said = '';
    /** @type {string} what the description says now */
    this.description = '';
    /** whether a new figure's description waits for the opening's edit (hold, release) */
    this.held = false;
    /** whether the last build drawn was final */
    this.final = false;
  }

  /**
   * Says a new figure once, politely (another scene, or an exercise: first what it asks), unless
   * it was said already.
   * @param {import('../store.js').StageState} state
   */
  announce(state) {
    const { scene, exercise: task } = state;
    if (!scene) return;
    const i18n = this.ports.i18n();
    const figure = `${scene.id} ${task?.id ?? ''} ${i18n.lang}`;
    if (figure === this.said) return;
    this.said = figure;
    this.ports.hush();
    const sentence = (/** @type {string} */ s) => (/[.!?…:]$/.test(s) ? s : `${s}.`);
    const asked = task
      ? `${i18n.t('task.heading')} ${sentence(say(task.title, i18n.lang))} ${say(task.prompt, i18n.lang)}`
      : '';
    this.ports.say([asked, this.spoken()].filter(Boolean).join(' '));
  }

  /**
   * Holds a new figure's description back: an opening whose edit comes next (the figure to say
   * is the edited one); `false` lets it go unsaid (an opening ended by another).
   */
  hold(on = true) {
    this.held = on;
  }

  /**
   * Says the figure held back, as it stands now (once its final build is drawn).
   * @param {import('../store.js').StageState} state
   */
  release(state) {
    this.held = false;
    if (this.final) this.announce(state);
  }

  /** What the figure shows, in words (as the description says it). */
  spoken() {
    return plainRich(this.description);
  }

  /**
   * Draws what a computation built (`final`: no heavier result is on its way), as the state stands.
   * @param {import('../store.js').StageState} state
   * @param {import('../scene.js').Built} built
   * @param {boolean} final
   */
  render(state, built, final) {
    const { els, mark } = this.ports;
    const { scene } = state;
    if (!scene) return;
    const i18n = this.ports.i18n();
    const { t } = i18n;
    const doc = els.root.ownerDocument;
    // a point on the move: the readout and the problems follow it; the rest waits for the move's
    // end (the same build is shown again then)
    const moving = state.moving && !!state.input;
    const problems = (built.problems ?? []).join('\n');
    if (els.problems.dataset.said !== problems || !moving) {
      els.problems.dataset.said = problems;
      els.problems.replaceChildren(...(built.problems ?? []).map((text) => appendRich(doc.createElement('li'), text)));
    }
    els.problems.hidden = !built.problems?.length;
    showReadout(els.readout, this.readouts(state, built), i18n);
    if (moving) {
      delete els.root.dataset.ready;
      return;
    }
    showLegend(els.legend, scene, state.params, t, built);
    // the legend may cover another share of a narrow view now: a fitted view is framed anew (not
    // while the reader moves the geometry: the view holds still under the pointer)
    if (!state.input) this.ports.refit();
    // an exercise hides what would give its answer away (the readout and the sentences that say it)
    const task = state.exercise;
    const hidden = task?.hide ?? [];
    showClaims(els.claims, hidden.includes('claims') ? [] : (built.claims ?? []), t);
    els.note.hidden = !built.note;
    els.note.textContent = built.note ?? '';
    const description = task && hidden.length ? say(task.title, i18n.lang) : built.description;
    this.description = description;
    els.description.replaceChildren();
    appendRich(els.description, description);
    els.caption.replaceChildren();
    appendRich(els.caption, description);
    this.final = final;
    if (final && !this.held) this.announce(state);
    const diagram = diagramOf(built);
    els.diagram.replaceChildren(...(diagram ? [diagram()] : []));
    els.downloads.replaceChildren(
      ...(built.downloads ?? []).map((d) => {
        const b = Object.assign(doc.createElement('button'), { type: 'button', textContent: t(d.label) });
        // (a file made when asked for may come later: a zip's library is loaded then)
        b.addEventListener('click', () => {
          Promise.resolve(typeof d.content === 'function' ? d.content() : d.content)
            .then((content) => download(d.filename, content, d.type))
            .catch((e) => this.fail(state, e));
        });
        return b;
      }),
    );
    for (const p of scene.params) mark(p.key, built.invalid?.[p.key] ?? null);
    els.root.dataset.scene = scene.id;
    els.root.dataset.paper = state.paper?.id ?? '';
    if (final) els.root.dataset.ready = '1';
    else delete els.root.dataset.ready;
  }

  /**
   * The readouts of `built` the reader may see (an exercise hides some).
   * @param {import('../store.js').StageState} state
   * @param {import('../scene.js').Built} built
   */
  readouts(state, built) {
    const hidden = state.exercise?.hide ?? [];
    return (built.readouts ?? []).filter((r) => !hidden.includes(r.label));
  }

  /**
   * Shows an error in the view (and next to the control it concerns), in the stage's language;
   * the last picture stays. Returns the sentence shown.
   */
  fail(/** @type {import('../store.js').StageState} */ state, /** @type {unknown} */ e) {
    const { els, mark } = this.ports;
    const { scene } = state;
    const option = /** @type {any} */ (e)?.details?.option;
    // the field it concerns: of the scene's candidates, the one the reader changed last
    const candidates = [scene && option ? scene.fieldOf?.(option) : null].flat().filter((k) => typeof k === 'string');
    const last = state.changed;
    const key = candidates.includes(last ?? '') ? last : (candidates[0] ?? null);
    // named as the page names it: the option's own name ("the interval of u"), else the field's
    const i18n = this.ports.i18n();
    const { t, has } = i18n;
    const name =
      option && has(`error.option.${option}`)
        ? t(`error.option.${option}`)
        : key
          ? this.fieldName(state, key)
          : undefined;
    const message = describeError(e, i18n, name);
    els.error.hidden = false;
    // beside its field the whole sentence; over the view (small on a phone) where to look
    els.error.textContent =
      key && state.controls ? t('error.seeField', { field: this.fieldName(state, key) }) : message;
    // the field the reader just changed keeps no old message when the error is now elsewhere (it
    // was fixed, or the core has not come to it: it says so again once the other is fixed)
    if (last && last !== key) mark(last, null);
    if (key) mark(key, message);
    // an edit the core cannot compute on: said under the readout too (the drag can go on, undo back)
    if (state.input) {
      els.problems.replaceChildren(Object.assign(els.root.ownerDocument.createElement('li'), { textContent: message }));
      els.problems.hidden = false;
    }
    this.ports.onError?.(e, message);
    // (settled: what is shown is the last picture and the error, until the reader changes something)
    els.root.dataset.ready = '1';
    return message;
  }

  /** The name of the field of parameter `key` in messages ("the z component of e(u)"), or its label. */
  fieldName(/** @type {import('../store.js').StageState} */ state, /** @type {string} */ key) {
    const p = state.scene?.params.find((q) => q.key === key);
    if (!p) return key;
    const { t, has } = this.ports.i18n();
    return has(`${p.label}.field`) ? t(`${p.label}.field`) : plainRich(t(p.label));
  }

  /** Notes about link values that were not used: read once, then out of the figure's way. */
  notes(/** @type {Array<{key: string, note: string, vars?: Record<string, string>}>} */ notes) {
    const { t } = this.ports.i18n();
    const box = this.ports.els.noteBox;
    const doc = box.ownerDocument;
    box.hidden = notes.length === 0;
    const close = Object.assign(doc.createElement('button'), {
      type: 'button',
      className: 'rl-note-close',
      textContent: '×',
    });
    close.setAttribute('aria-label', t('view.closeNote'));
    close.addEventListener('click', () => (box.hidden = true));
    const text = doc.createElement('span');
    text.textContent = notes.map(({ key, note, vars }) => t(note, { key, ...vars })).join(' ');
    box.replaceChildren(text, close);
  }
}
