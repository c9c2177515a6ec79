// The readout: the numbers a scene measures, as a definition list, formatted for the language
// ("exact" where an error is 0 to rounding).
import { appendRich, plainRich } from './richtext.js';

/**
 * @param {HTMLElement} list   a <dl>
 * @param {import('../scene.js').Readout[]} readouts
 * @param {import('../i18n/index.js').Translator} i18n
 */
export function showReadout(list, readouts, { t, format }) {
  const doc = list.ownerDocument;
  list.replaceChildren(
    ...readouts.flatMap(({ label, value, exactZero }) => {
      const shown = exactZero && typeof value === 'number' && Math.abs(value) < 1e-13 ? t('readout.exact') : typeof value === 'number' ? format(value) : t(String(value));
      return [appendRich(doc.createElement('dt'), t(label)), Object.assign(doc.createElement('dd'), { textContent: shown })];
    }),
  );
  list.hidden = readouts.length === 0;
}

/** The readout as one sentence for screen readers: "label: value; …". */
export function readoutSentence(/** @type {import('../scene.js').Readout[]} */ readouts, /** @type {import('../i18n/index.js').Translator} */ { t, format }) {
  return readouts
    .map(({ label, value, exactZero }) => {
      const shown = exactZero && typeof value === 'number' && Math.abs(value) < 1e-13 ? t('readout.exact') : typeof value === 'number' ? format(value) : t(String(value));
      return `${plainRich(t(label))}: ${shown}`;
    })
    .join('; ');
}
