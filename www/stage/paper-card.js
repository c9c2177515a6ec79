// The card of the paper's figure a stage shows (if any): its caption, what ruledlab shows and
// whose data it is, where ruledlab goes beyond the paper, and — once a control has moved — the
// way back to the figure's own settings. It reads the stage's state; the way back is a change the
// stage makes (Stage.backToPaper).
import { appendRich } from '../ui/richtext.js';
import { atPreset } from '../paper.js';

export class PaperCard {
  /** @param {import('../stage.js').Stage} stage */
  constructor(stage) {
    this.stage = stage;
    /** @type {boolean | undefined} whether the reader opened (or closed) the card */
    this.open = undefined;
  }

  /** Shows the card as the state stands (none in an exercise). */
  show() {
    const stage = this.stage;
    const card = stage.els.paperCard;
    const { scene, params } = stage;
    const preset = stage.task ? null : stage.paper;
    card.hidden = !preset || !scene;
    if (!preset || !scene) return card.replaceChildren();
    const { t } = stage.i18n;
    const doc = card.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {string} */ className, /** @type {string} */ text) =>
      appendRich(Object.assign(doc.createElement(tag), { className }), text);
    const heading = el('h3', 'rl-paper-title', t('paper.heading', { figure: t(preset.label) }));
    heading.id = `${card.id}-title`;
    card.setAttribute('aria-labelledby', heading.id);
    const caption = el('blockquote', 'rl-paper-caption', t(preset.caption));
    const note = el('p', 'rl-paper-note', t(preset.note));
    const data = el('p', `rl-paper-data rl-data-${preset.data}`, t(`paper.data.${preset.data}`));
    // the heading opens and closes the rest: open beside the view, closed over the controls of a
    // narrow box (one line instead of a screenful before the first slider), as the reader left it
    const more = /** @type {HTMLDetailsElement} */ (doc.createElement('details'));
    more.className = 'rl-paper-more';
    more.open = this.open ?? !stage.els.root.classList.contains('rl-narrow');
    more.addEventListener('toggle', () => (this.open = more.open));
    const summary = doc.createElement('summary');
    summary.append(heading);
    more.append(summary, caption, note, data);
    card.replaceChildren(more);
    if (preset.beyond) {
      const beyond = doc.createElement('p');
      beyond.className = 'rl-beyond';
      beyond.append(Object.assign(doc.createElement('strong'), { textContent: `${t('paper.beyondTitle')} ` }));
      appendRich(beyond, t(preset.beyond));
      more.append(beyond);
    }
    if (!atPreset(preset, scene, params)) {
      const changed = el('p', 'rl-paper-changed', `${t('paper.changed')} `);
      const back = Object.assign(doc.createElement('button'), {
        type: 'button',
        textContent: t('paper.back', { figure: t(preset.label) }),
      });
      back.addEventListener('click', () => stage.backToPaper());
      changed.append(back);
      card.append(changed);
    }
  }
}
