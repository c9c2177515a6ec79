// The readout: the numbers a scene measures, as a definition list, formatted for the language
// ("exact" where an error is 0 to rounding).
import { appendRich, plainRich } from './richtext.js';
import { EXACT_ZERO } from '../limits.js';

/**
 * @param {HTMLElement} list   a <dl>
 * @param {import('../scene.js').Readout[]} readouts
 * @param {import('../i18n/index.js').Translator} i18n
 */
export function showReadout(list, readouts, { t, format }) {
  const doc = list.ownerDocument;
  // the same labels as shown (a drag's frame, a slider moved): only the values that changed are
  // written, so the panel is not laid out anew for every frame
  const labels = readouts.map(({ label }) => t(label)).join('\n');
  if (list.dataset.labels === labels) {
    const values = list.querySelectorAll('dd');
    readouts.forEach(({ value, exactZero }, i) => {
      const shown = valueText(value, exactZero, { t, format });
      if (values[i] && values[i].textContent !== shown) values[i].textContent = shown;
    });
    return;
  }
  list.dataset.labels = labels;
  list.replaceChildren(
    ...readouts.flatMap(({ label, value, exactZero }) => {
      const shown = valueText(value, exactZero, { t, format });
      return [
        appendRich(doc.createElement('dt'), t(label)),
        Object.assign(doc.createElement('dd'), { textContent: shown }),
      ];
    }),
  );
  list.hidden = readouts.length === 0;
}

/** The readout as one sentence for screen readers: "label: value; …". */
export function readoutSentence(
  /** @type {import('../scene.js').Readout[]} */ readouts,
  /** @type {import('../i18n/index.js').Translator} */ { t, format },
) {
  return readouts
    .map(({ label, value, exactZero }) => {
      const shown = valueText(value, exactZero, { t, format });
      return `${plainRich(t(label))}: ${shown}`;
    })
    .join('; ');
}

/**
 * The comparative sentences of the scene, each marked with whether the readout bears it out
 * at these settings (✓ holds here, ✗ not at these settings).
 * @param {HTMLElement} list   a <ul>
 * @param {import('../scene.js').Claim[]} claims
 * @param {(key: string) => string} t
 */
export function showClaims(list, claims, t) {
  const doc = list.ownerDocument;
  list.replaceChildren(
    ...claims.map(({ text, holds }) => {
      const li = doc.createElement('li');
      li.className = holds ? 'rl-holds' : 'rl-fails';
      li.dataset.claim = text;
      const mark = Object.assign(doc.createElement('span'), { className: 'rl-mark', textContent: holds ? '✓' : '✗' });
      mark.setAttribute('aria-hidden', 'true');
      const status = Object.assign(doc.createElement('span'), {
        className: 'rl-sr-only',
        textContent: `${t(holds ? 'claim.holds' : 'claim.fails')}: `,
      });
      li.append(mark, status);
      appendRich(li, t(text));
      return li;
    }),
  );
  list.hidden = claims.length === 0;
  if (claims.length) list.setAttribute('aria-label', t('claim.title'));
}

/**
 * A readout's value as shown: "exact" for an exact zero, a number in the language's format, or
 * the translation of a key.
 * @param {import('../scene.js').Readout['value']} value
 * @param {boolean | undefined} exactZero
 * @param {Pick<import('../i18n/index.js').Translator, 't' | 'format'>} i18n
 */
export function valueText(value, exactZero, { t, format }) {
  if (exactZero && typeof value === 'number' && Math.abs(value) < EXACT_ZERO) return t('readout.exact');
  return typeof value === 'number' ? format(value) : t(String(value));
}
