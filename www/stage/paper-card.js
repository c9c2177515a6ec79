// The card of the paper's figure a stage shows (if any): its caption, what ruledlab shows and
// whose data it is, where ruledlab goes beyond the paper, and — once a control has moved — the
// way back to the figure's own settings. It draws from the state (render); the way back is asked
// of the stage (`back`).
import { appendRich } from '../ui/richtext.js';
import { atPreset } from '../paper.js';

export class PaperCard {
  /**
   * @param {HTMLElement} card   its place in the panel
   * @param {{i18n: () => import('../i18n/index.js').Translator, narrow: () => boolean, back: () => void}} ports
   *   narrow: the stage's box is narrow (the card starts closed there); back: the figure's settings again
   */
  constructor(card, ports) {
    this.card = card;
    this.ports = ports;
    /** @type {boolean | undefined} whether the reader opened (or closed) the card */
    this.open = undefined;
  }

  /** Draws the card as the state stands (none in an exercise). @param {import('../store.js').StageState} state */
  render(state) {
    const card = this.card;
    const { scene, params } = state;
    const preset = state.exercise ? null : state.paper;
    card.hidden = !preset || !scene;
    if (!preset || !scene) return card.replaceChildren();
    const { t } = this.ports.i18n();
    const doc = card.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {string} */ className, /** @type {string} */ text) =>
      appendRich(Object.assign(doc.createElement(tag), { className }), text);
    // the heading holds the button that opens and closes the rest (a heading inside a <summary>
    // is no heading to a screen reader): open beside the view, closed over the controls of a
    // narrow box (one line instead of a screenful before the first slider), as the reader left it
    const heading = doc.createElement('h3');
    heading.className = 'rl-paper-title';
    heading.id = `${card.id}-title`;
    card.setAttribute('aria-labelledby', heading.id);
    const toggle = /** @type {HTMLButtonElement} */ (
      el('button', 'rl-paper-toggle', t('paper.heading', { figure: t(preset.label) }))
    );
    toggle.type = 'button';
    heading.append(toggle);
    const caption = el('blockquote', 'rl-paper-caption', t(preset.caption));
    const note = el('p', 'rl-paper-note', t(preset.note));
    const data = el('p', `rl-paper-data rl-data-${preset.data}`, t(`paper.data.${preset.data}`));
    const more = doc.createElement('div');
    more.className = 'rl-paper-more';
    more.id = `${card.id}-more`;
    toggle.setAttribute('aria-controls', more.id);
    const shown = (/** @type {boolean} */ open) => {
      more.hidden = !open;
      toggle.setAttribute('aria-expanded', String(open));
    };
    shown(this.open ?? !this.ports.narrow());
    toggle.addEventListener('click', () => {
      this.open = more.hidden;
      shown(this.open);
    });
    more.append(caption, note, data);
    card.replaceChildren(heading, more);
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
      back.addEventListener('click', () => this.ports.back());
      changed.append(back);
      card.append(changed);
    }
  }
}
