// The page's chrome above the stage: the skip link, the title, the scene, figure and language
// pickers and the Share button, with their texts in the reader's language.
import { SCENES } from '../scenes/index.js';
import { PRESETS } from '../paper.js';
import { LANGUAGE_CODES } from '../i18n/translate.js';
import { builtInTasks } from '../task/builtin.js';
import { solvedTasks } from '../task/progress.js';
import { say } from '../task/format.js';

/** The page's language names, in their own language. */
const NATIVE = { en: 'English', de: 'Deutsch' };

/** A title without the markup of sub- and superscripts (for menus and the tab). */
export const plainTitle = (/** @type {string} */ text) => text.replace(/[_^]\{?([^}]*)\}?/g, '$1');

/**
 * The header of the page and the <main> the stage fills, put into `doc.body`.
 * @param {Document} doc
 */
export function pageChrome(doc) {
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
    Object.assign(doc.createElement(tag), props);
  const skip = el('a', { className: 'skip', href: '#main' });
  skip.addEventListener('click', (e) => {
    e.preventDefault();
    /** @type {HTMLElement | null} */ (doc.querySelector('.rl-controls [name]'))?.focus();
  });
  const header = el('header', { className: 'page-header' });
  const title = el('h1', { textContent: 'ruledlab' });
  const subtitle = el('p', { className: 'subtitle' });
  const pickerLabel = el('label', { className: 'picker' });
  const picker = /** @type {HTMLSelectElement} */ (el('select', { id: 'scene' }));
  pickerLabel.append(el('span'), picker);
  const paperLabel = el('label', { className: 'picker' });
  const paperPicker = /** @type {HTMLSelectElement} */ (el('select', { id: 'paper' }));
  paperLabel.append(el('span'), paperPicker);
  const taskLabel = el('label', { className: 'picker' });
  const taskPicker = /** @type {HTMLSelectElement} */ (el('select', { id: 'task' }));
  taskLabel.append(el('span'), taskPicker);
  const langLabel = el('label', { className: 'picker' });
  const langPicker = /** @type {HTMLSelectElement} */ (el('select', { id: 'lang' }));
  for (const code of LANGUAGE_CODES) {
    langPicker.add(new Option(NATIVE[/** @type {keyof typeof NATIVE} */ (code)] ?? code, code));
  }
  langLabel.append(el('span'), langPicker);
  const shareButton = el('button', { type: 'button', id: 'share' });
  header.append(title, subtitle, pickerLabel, paperLabel, taskLabel, langLabel, shareButton);
  const main = el('main', { id: 'main' });
  doc.body.replaceChildren(skip, header, main);

  /** The label text before a picker. */
  const label = (/** @type {HTMLElement} */ box, /** @type {string} */ text) => {
    /** @type {Text} */ (box.firstChild).textContent = `${text} `;
  };
  return {
    main,
    picker,
    paperPicker,
    taskPicker,
    langPicker,
    shareButton,
    /**
     * The texts in the current language, the pickers showing what is on screen.
     * @param {import('../i18n/index.js').Translator} i18n
     * @param {string} lang
     * @param {{ scene: string | null, paper: string | null, task?: string | null }} shown
     */
    localize({ t }, lang, shown) {
      subtitle.textContent = t('app.subtitle');
      skip.textContent = t('app.skip');
      label(pickerLabel, t('app.scene'));
      label(langLabel, t('app.language'));
      label(paperLabel, t('app.figures'));
      langPicker.value = lang;
      picker.replaceChildren(...SCENES.map((s) => new Option(plainTitle(t(s.title)), s.id)));
      if (shown.scene) picker.value = shown.scene;
      paperPicker.replaceChildren(
        new Option(t('paper.none'), ''),
        ...PRESETS.map((p) => new Option(plainTitle(t(p.label)), p.id)),
      );
      paperPicker.value = shown.paper ?? '';
      label(taskLabel, t('app.exercises'));
      // the built-in exercises, the solved ones marked (in words for screen readers as well)
      const solved = solvedTasks();
      taskPicker.replaceChildren(
        new Option(t('task.none'), ''),
        ...builtInTasks().map(
          (task) => new Option(`${solved.has(task.id) ? '✓ ' : ''}${say(task.title, lang)}`, task.id),
        ),
      );
      taskPicker.value = shown.task && builtInTasks().some((x) => x.id === shown.task) ? shown.task : '';
      shareButton.textContent = t('app.share');
    },
  };
}
