// Why ruledlab could not start, shown where the view would be: the page's boot box, or inside
// a <ruled-view> that cannot make its view (no WebGL2).
import { startFailure } from './errors.js';

/**
 * Fills `box` with why ruledlab could not start: a sentence in the reader's language, and the
 * browser's own message folded away (in English, for a bug report).
 * @param {HTMLElement} box
 * @param {unknown} e
 * @param {import('../i18n/index.js').Translator} i18n
 */
export function showFailure(box, e, i18n) {
  const doc = box.ownerDocument;
  const { text, technical } = startFailure(e, i18n);
  box.className = 'boot boot-problem';
  box.setAttribute('role', 'alert');
  const more = doc.createElement('details');
  const summary = Object.assign(doc.createElement('summary'), { textContent: i18n.t('boot.technical') });
  const code = Object.assign(doc.createElement('code'), { textContent: technical, lang: 'en' });
  more.append(summary, code);
  box.replaceChildren(doc.createTextNode(`${text} `), more);
}
