// Exercises as files a course system takes — a SCORM 1.2 or SCORM 2004 package, an .h5p file —
// made in the browser from the page's own files (the one-file page, its embed script: fetched
// from the site, or this very document when it is the one-file page) and downloaded. Share and
// the author offer the same three buttons; what goes wrong is said under them in the page's
// language.
import { download } from '../ui/download.js';
import { oneFileHtml } from './onefile.js';
import { taskErrorText } from '../task/words.js';
import { builtInTasks } from '../task/builtin.js';
import { say } from '../task/format.js';
import { undrawn } from '../task/draw.js';
import { MAX_PACKAGE_TASKS, MAX_TASK_TITLE } from '../limits.js';

/** Exercises made with the author during this visit, offered for a package of several. */
const made = /** @type {import('../task/format.js').Task[]} */ ([]);

/** Remembers an exercise made with the author (the newest version of an id replaces the older). */
export function remember(/** @type {import('../task/format.js').Task} */ task) {
  const k = made.findIndex((t) => t.id === task.id);
  if (k >= 0) made.splice(k, 1);
  made.unshift(task);
}

/**
 * @typedef {import('../task/format.js').Task} Task
 *
 * @typedef {object} PackageSource
 * @property {boolean} oneFile     this page is the one-file build
 * @property {(() => string) | undefined} embedScript   its own script (the embed script)
 */

/** A package's error in the reader's words (its own reasons, course.error.*, or the exercise's). */
export function packageErrorText(/** @type {unknown} */ e, /** @type {import('../i18n/index.js').Translator} */ i18n) {
  const details = /** @type {any} */ (e)?.details;
  if (typeof details?.reason === 'string' && details.reason.startsWith('course.') && i18n.has(details.reason))
    return i18n.t(details.reason, details.args ?? {});
  return taskErrorText(e, i18n);
}

/**
 * @typedef {PackageSource & {lang: string, readers: import('../course/scorm-package.js').Readers, title?: string,
 *   draw?: 'attempt' | 'learner'}} PackageOptions
 */

/**
 * Makes and downloads a package of `tasks` (several: one activity, the score their sum).
 * @param {'scorm12' | 'scorm2004' | 'h5p'} kind
 * @param {Task[]} tasks
 * @param {PackageOptions} options
 */
export async function downloadPackage(kind, tasks, options) {
  const name =
    tasks
      .map((t) => t.id)
      .join('-')
      .slice(0, 80) || 'exercise';
  if (kind === 'h5p') {
    const { h5pPackage } = await import('../course/h5p-package.js');
    const bytes = await h5pPackage(tasks, {
      lang: options.lang,
      readers: options.readers,
      title: options.title,
      draw: options.draw,
      script: options.embedScript?.() || undefined,
    });
    download(`${name}.h5p`, new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)], { type: 'application/zip' }));
    return;
  }
  const { scormPackage } = await import('../course/scorm-package.js');
  const bytes = await scormPackage(tasks, {
    standard: kind,
    lang: options.lang,
    readers: options.readers,
    title: options.title,
    draw: options.draw,
    page: await oneFileHtml(options.oneFile),
  });
  download(
    `${name}-${kind}.zip`,
    new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)], { type: 'application/zip' }),
  );
}

/**
 * What a package holds, as its button says it: the activity's title and how many exercises, or
 * the first exercise's title and how many more.
 * @param {import('../i18n/index.js').Translator} i18n
 * @param {Task[]} tasks
 * @param {string} title   the activity's title typed ('' : none)
 */
export function packageWhat({ t, lang }, tasks, title) {
  if (title) return t('course.what.titled', { title, count: tasks.length });
  const first = say(undrawn(tasks[0].title, tasks[0]), lang);
  return tasks.length > 1
    ? t('course.what.more', { title: first, count: tasks.length - 1 })
    : t('course.what.one', { title: first });
}

/**
 * The package buttons (SCORM 1.2, SCORM 2004, H5P) for the exercise `tasks()` gives, each saying
 * what it packages, with the activity's title, how numbers are drawn and a note under them for
 * what goes wrong; more exercises (built-in ones, those made here) may be ticked under "More
 * exercises": one activity, the score their sum, in either format.
 * @param {Document} doc
 * @param {() => import('../i18n/index.js').Translator} i18n
 * @param {() => Task[]} tasks
 * @param {() => PackageOptions} options
 * @param {string} prefix   the controls' names ("share", "author")
 */
export function packageButtons(doc, i18n, tasks, options, prefix) {
  const { t } = i18n();
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
    Object.assign(doc.createElement(tag), props);
  const box = el('div', { className: 'rl-packages' });
  const note = el('p', { className: 'share-note rl-package-note', hidden: true });
  note.setAttribute('role', 'status');
  box.append(el('p', { textContent: t('course.packages') }));
  // more exercises for one activity
  const more = doc.createElement('details');
  more.className = 'rl-package-more';
  more.append(el('summary', { textContent: t('course.more', { max: MAX_PACKAGE_TASKS }) }));
  const lang = i18n().lang;
  const first = new Set(tasks().map((x) => x.id));
  const offered = [...made, ...builtInTasks()].filter(
    (x, k, all) => !first.has(x.id) && all.findIndex((y) => y.id === x.id) === k,
  );
  /** @type {Array<[HTMLInputElement, import('../task/format.js').Task]>} */
  const ticks = offered.map((task) => {
    const input = /** @type {HTMLInputElement} */ (
      el('input', { type: 'checkbox', name: `${prefix}-more-${task.id}` })
    );
    const label = el('label', { className: 'rl-package-task' });
    label.append(input, ` ${say(undrawn(task.title, task), lang)}`);
    more.append(label);
    return [input, task];
  });
  const chosen = () =>
    [...tasks(), ...ticks.filter(([input]) => input.checked).map(([, task]) => task)].slice(0, MAX_PACKAGE_TASKS);
  // the activity's title as the course shows it, and how numbers are drawn
  const title = el('input', {
    type: 'text',
    name: `${prefix}-package-title`,
    maxLength: MAX_TASK_TITLE,
    spellcheck: true,
  });
  const titleRow = el('label', { className: 'rl-package-field' });
  titleRow.append(el('span', { textContent: t('course.activityTitle') }), title);
  const draw = /** @type {HTMLSelectElement} */ (el('select', { name: `${prefix}-package-draw` }));
  for (const v of ['attempt', 'learner']) draw.add(new Option(t(`course.draw.${v}`), v));
  const drawRow = el('label', { className: 'rl-package-field' });
  drawRow.append(el('span', { textContent: t('course.draw') }), draw);
  box.append(more, titleRow, drawRow);
  /** @type {Array<[HTMLButtonElement, 'scorm12' | 'scorm2004' | 'h5p']>} */
  const buttons = [];
  /** The buttons say what they package (again when the title or the exercises ticked change). */
  const label = () => {
    const what = packageWhat(i18n(), chosen(), title.value.trim());
    for (const [button, kind] of buttons) button.textContent = t(`course.packageOf.${kind}`, { what });
    // (numbers are drawn only where an exercise draws them)
    drawRow.hidden = !chosen().some((x) => Object.keys(x.draw).length);
  };
  title.addEventListener('input', label);
  more.addEventListener('change', label);
  for (const kind of /** @type {const} */ (['scorm12', 'scorm2004', 'h5p'])) {
    const button = /** @type {HTMLButtonElement} */ (el('button', { type: 'button', name: `${prefix}-${kind}` }));
    button.addEventListener('click', async () => {
      note.hidden = true;
      button.disabled = true;
      try {
        const list = chosen();
        const opts = options();
        await downloadPackage(kind, list, {
          ...opts,
          title: title.value.trim() || (list.length > 1 ? undefined : opts.title),
          draw: /** @type {'attempt' | 'learner'} */ (draw.value),
        });
        note.hidden = false;
        note.textContent = t(`course.made.${kind === 'h5p' ? 'h5p' : 'scorm'}`);
      } catch (e) {
        note.hidden = false;
        note.textContent = t('course.notMade', { reason: packageErrorText(e, i18n()) });
      } finally {
        button.disabled = false;
      }
    });
    buttons.push([button, kind]);
    box.append(button);
  }
  label();
  box.append(note);
  return box;
}
