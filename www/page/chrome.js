// The page's chrome above the stage: the skip link, the title, the scene, figure, exercise and
// language pickers and the Share button (on a phone behind one Menu button), with their texts in
// the reader's language.
import { SCENES } from '../scenes/index.js';
import { PRESETS } from '../paper.js';
import { LANGUAGE_CODES } from '../i18n/translate.js';
import { builtInTasks } from '../task/builtin.js';
import { solvedTasks } from '../task/progress.js';
import { say } from '../task/format.js';
import { undrawn } from '../task/draw.js';
import { plainRich } from '../ui/richtext.js';

/** The page's language names, in their own language. */
const NATIVE = { en: 'English', de: 'Deutsch' };

/** A title in plain text, its scripts as everywhere (for menus and the tab: "R_{i}" → "Rᵢ"). */
export const plainTitle = (/** @type {string} */ text) => plainRich(text);

/** Text as HTML (for the shell's markup). */
export const htmlText = (/** @type {string} */ text) =>
  text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c] ?? c);

/**
 * The markup of the skip link and the header in English, before any script: the production page
 * and the one-file build carry it in their HTML (page/shell.js), so that it is painted with the
 * first bytes; pageChrome() takes it over, or puts it in where the page has none (npm run dev).
 * On a phone the header is one row: the name and the Menu button, which opens the pickers and
 * Share over the figure.
 * @param {import('../i18n/index.js').Translator} i18n   English
 */
export function chromeHtml({ t }) {
  const picker = (/** @type {string} */ id, /** @type {string} */ label, /** @type {string} */ options) =>
    `<label class="picker"><span>${htmlText(t(label))} </span><select id="${id}">${options}</select></label>`;
  /** An option; `lang`: the language its text is in, where it is not the page's. */
  const option = (/** @type {string} */ value, /** @type {string} */ text, lang = '') =>
    `<option value="${htmlText(value)}"${lang ? ` lang="${htmlText(lang)}"` : ''}>${htmlText(text)}</option>`;
  // each language's name in that language, and read in it
  const name = (/** @type {string} */ code) => NATIVE[/** @type {keyof typeof NATIVE} */ (code)] ?? code;
  const languages = LANGUAGE_CODES.map((code) => option(code, name(code), code)).join('');
  return [
    `<a class="skip" href="#main">${htmlText(t('app.skip'))}</a>`,
    '<header class="page-header">',
    '<h1>ruledlab</h1>',
    `<p class="subtitle">${htmlText(t('app.subtitle'))}</p>`,
    `<button type="button" id="menu" class="menu" aria-expanded="false" aria-controls="page-menu"><span class="menu-sign" aria-hidden="true">☰</span> <span class="menu-word">${htmlText(t('app.menu'))}</span></button>`,
    '<div class="page-menu" id="page-menu">',
    picker('scene', 'app.scene', SCENES.map((s) => option(s.id, plainTitle(t(s.title)))).join('')),
    picker('paper', 'app.figures', option('', t('paper.none'))),
    picker('task', 'app.exercises', option('', t('task.none'))),
    picker('lang', 'app.language', languages),
    `<button type="button" id="share">${htmlText(t('app.share'))}</button>`,
    '</div>',
    '</header>',
  ].join('');
}

/**
 * The header of the page and the <main> the stage fills: taken over from the page's shell where
 * its HTML has one, else put into `doc.body`.
 * @param {Document} doc
 * @param {import('../i18n/index.js').Translator} english
 */
export function pageChrome(doc, english) {
  if (!doc.querySelector('header.page-header')) {
    doc.body.innerHTML = `${chromeHtml(english)}<main id="main"></main>`;
  }
  const by = (/** @type {string} */ selector) => /** @type {HTMLElement} */ (doc.querySelector(selector));
  const skip = by('a.skip');
  // to the first field or button that takes the keyboard: the exercise's (where its held controls
  // are disabled), else the scene's controls, else anything in the panel
  skip.addEventListener('click', (e) => {
    e.preventDefault();
    const takes = ':is(input, select, textarea, button, [tabindex="0"]):not(:disabled, [tabindex="-1"])';
    const first = ['.rl-task:not([hidden])', '.rl-controls', '.rl-panel']
      .flatMap((part) => [...doc.querySelectorAll(`${part} ${takes}`)])
      .find((c) => c instanceof HTMLElement && c.offsetParent !== null);
    /** @type {HTMLElement | undefined} */ (first)?.focus();
  });
  const header = by('header.page-header');
  const subtitle = by('.page-header .subtitle');
  const picker = /** @type {HTMLSelectElement} */ (by('#scene'));
  const paperPicker = /** @type {HTMLSelectElement} */ (by('#paper'));
  const taskPicker = /** @type {HTMLSelectElement} */ (by('#task'));
  const langPicker = /** @type {HTMLSelectElement} */ (by('#lang'));
  const [pickerLabel, paperLabel, taskLabel, langLabel] = [picker, paperPicker, taskPicker, langPicker].map(
    (p) => /** @type {HTMLElement} */ (p.parentElement),
  );
  const shareButton = /** @type {HTMLButtonElement} */ (by('#share'));
  const menuButton = /** @type {HTMLButtonElement} */ (by('#menu'));
  const main = by('#main');

  // the phone's menu: opened and closed by its button, closed by Escape, a click elsewhere, or
  // once a choice is made in it
  const open = (/** @type {boolean} */ on) => {
    header.classList.toggle('open', on);
    menuButton.setAttribute('aria-expanded', String(on));
  };
  menuButton.addEventListener('click', () => open(!header.classList.contains('open')));
  header.addEventListener('keydown', (e) => {
    if (e.key === 'Escape' && header.classList.contains('open')) {
      open(false);
      menuButton.focus();
    }
  });
  doc.addEventListener('pointerdown', (e) => {
    if (header.classList.contains('open') && !header.contains(/** @type {Node} */ (e.target))) open(false);
  });
  // … and when the keyboard leaves it (Tab past Share would go on under it)
  header.addEventListener('focusout', (e) => {
    const to = e.relatedTarget;
    if (header.classList.contains('open') && to instanceof Node && !header.contains(to)) open(false);
  });
  shareButton.addEventListener('click', () => open(false));
  for (const control of [picker, paperPicker, taskPicker, langPicker]) onChosen(control, () => open(false));

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
          (task) => new Option(`${solved.has(task.id) ? '✓ ' : ''}${say(undrawn(task.title, task), lang)}`, task.id),
        ),
      );
      taskPicker.value = shown.task && builtInTasks().some((x) => x.id === shown.task) ? shown.task : '';
      shareButton.textContent = t('app.share');
      /** @type {HTMLElement} */ (menuButton.querySelector('.menu-word')).textContent = t('app.menu');
    },
  };
}

/** How long a choice made by stepping through a closed menu with keys waits for the next step (ms). */
const STEPPED = 600;

/**
 * Calls `act` when the reader has chosen in `select`: at once when chosen by the mouse, a finger
 * or Enter, but after a pause when the arrow keys step through the closed menu (each step would
 * otherwise open another scene or exercise, and say it, on the way to the one wanted); Enter or
 * leaving the menu acts at once on a step that waits.
 * @param {HTMLSelectElement} select
 * @param {() => void} act
 */
export function onChosen(select, act) {
  let stepped = 0;
  let timer = 0;
  const now = () => {
    clearTimeout(timer);
    if (timer) {
      timer = 0;
      act();
    }
  };
  select.addEventListener('keydown', (e) => {
    if (/^(Arrow(Up|Down|Left|Right)|Home|End|Page(Up|Down))$/.test(e.key)) stepped = performance.now();
    else if (e.key === 'Enter') now();
  });
  select.addEventListener('blur', now);
  select.addEventListener('change', () => {
    clearTimeout(timer);
    timer = 0;
    if (performance.now() - stepped < 100) timer = window.setTimeout(now, STEPPED);
    else act();
  });
}
