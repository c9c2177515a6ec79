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
import { MAX_PACKAGE_TASKS } from '../limits.js';

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
 * Makes and downloads a package of `tasks`.
 * @param {'scorm12' | 'scorm2004' | 'h5p'} kind
 * @param {Task[]} tasks
 * @param {PackageSource & {lang: string, readers: import('../course/scorm-package.js').Readers, title?: string}} options
 */
export async function downloadPackage(kind, tasks, options) {
  const name =
    tasks
      .map((t) => t.id)
      .join('-')
      .slice(0, 80) || 'exercise';
  if (kind === 'h5p') {
    const { h5pPackage } = await import('../course/h5p-package.js');
    const bytes = await h5pPackage(tasks[0], {
      lang: options.lang,
      readers: options.readers,
      title: options.title,
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
    page: await oneFileHtml(options.oneFile),
  });
  download(
    `${name}-${kind}.zip`,
    new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)], { type: 'application/zip' }),
  );
}

/**
 * The three buttons (SCORM 1.2, SCORM 2004, H5P) for the exercise `tasks()` gives, with a note
 * under them for what goes wrong; a SCORM package may take more exercises (built-in ones, those
 * made here), ticked under "More exercises in the SCORM package": one activity, the score their sum.
 * @param {Document} doc
 * @param {() => import('../i18n/index.js').Translator} i18n
 * @param {() => Task[]} tasks
 * @param {() => PackageSource & {lang: string, readers: import('../course/scorm-package.js').Readers, title?: string}} options
 * @param {string} prefix   the buttons' names ("share", "author")
 */
export function packageButtons(doc, i18n, tasks, options, prefix) {
  const { t } = i18n();
  const box = Object.assign(doc.createElement('div'), { className: 'rl-packages' });
  const note = Object.assign(doc.createElement('p'), { className: 'share-note rl-package-note', hidden: true });
  note.setAttribute('role', 'status');
  box.append(Object.assign(doc.createElement('p'), { textContent: t('course.packages') }));
  // more exercises for one SCORM package
  const more = doc.createElement('details');
  more.className = 'rl-package-more';
  more.append(
    Object.assign(doc.createElement('summary'), { textContent: t('course.more', { max: MAX_PACKAGE_TASKS }) }),
  );
  const lang = i18n().lang;
  const first = new Set(tasks().map((x) => x.id));
  const offered = [...made, ...builtInTasks()].filter(
    (x, k, all) => !first.has(x.id) && all.findIndex((y) => y.id === x.id) === k,
  );
  /** @type {Array<[HTMLInputElement, import('../task/format.js').Task]>} */
  const ticks = offered.map((task) => {
    const input = Object.assign(doc.createElement('input'), { type: 'checkbox', name: `${prefix}-more-${task.id}` });
    const label = Object.assign(doc.createElement('label'), { className: 'rl-package-task' });
    label.append(input, ` ${say(undrawn(task.title, task), lang)}`);
    more.append(label);
    return [input, task];
  });
  const chosen = () => [...tasks(), ...ticks.filter(([input]) => input.checked).map(([, task]) => task)];
  box.append(more);
  for (const kind of /** @type {const} */ (['scorm12', 'scorm2004', 'h5p'])) {
    const button = Object.assign(doc.createElement('button'), {
      type: 'button',
      name: `${prefix}-${kind}`,
      textContent: t(`course.package.${kind}`),
    });
    button.addEventListener('click', async () => {
      note.hidden = true;
      button.disabled = true;
      try {
        // (an H5P file holds one exercise; a package of several is named after all of them)
        const list = kind === 'h5p' ? tasks() : chosen();
        const opts = options();
        await downloadPackage(kind, list, list.length > 1 ? { ...opts, title: undefined } : opts);
        note.hidden = false;
        note.textContent = t(`course.made.${kind === 'h5p' ? 'h5p' : 'scorm'}`);
      } catch (e) {
        note.hidden = false;
        note.textContent = t('course.notMade', { reason: packageErrorText(e, i18n()) });
      } finally {
        button.disabled = false;
      }
    });
    box.append(button);
  }
  box.append(note);
  return box;
}
