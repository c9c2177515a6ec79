// An H5P file (.h5p) of an exercise or a problem set of several, which Moodle's and ILIAS's H5P
// activities play and record: h5p.json, content/content.json (the exercises, the activity's
// title, what readers may do, when the solution is offered and how numbers are drawn), and the
// content type's library H5P.RuledlabExercise-1.0 (library.json, semantics.json for H5P's editor
// — every field of content.json, since H5P drops what semantics.json does not name — a German
// translation of the editor's labels, and the viewer: the embed script, dist/ruledlab-embed.js,
// which registers the content type where H5P runs it — course/h5p-type.js). Only files H5P
// allows in a library (json, js): the core travels inside the script, as text, not as a .wasm
// file, which H5P's whitelist refuses. A course system installs the library from the first .h5p
// an administrator allows to carry one.
import { say, writeTask } from '../task/format.js';
import { builtInTask } from '../task/builtin.js';
import { makeZip, PackageError, readZip, text } from './zip.js';
import { packageTasks } from './scorm-package.js';
import { undrawn } from '../task/draw.js';
import { H5P_LIBRARY, h5pExercises } from './h5p-exercise.js';
import { H5P_HEIGHT, MAX_PACKAGE_TASKS, MAX_SOLUTION_AFTER, MAX_TASK, MAX_TASK_TITLE } from '../limits.js';

export { H5P_LIBRARY } from './h5p-exercise.js';

/** The content type's library version. */
export const H5P_MAJOR = 1;
export const H5P_MINOR = 0;
/**
 * The library's patch version: ruledlab's version as one number (0.1.0 → 100), so that a newer
 * ruledlab's .h5p replaces the library a course system has (H5P updates a library only to a
 * higher patch version). tests/node/course.test.mjs holds it to package.json's version.
 */
export const H5P_PATCH = 100;
/** The library's folder in an .h5p file. */
export const H5P_FOLDER = `${H5P_LIBRARY}-${H5P_MAJOR}.${H5P_MINOR}`;
/** The viewer's file in the library: the embed script. */
export const H5P_SCRIPT = 'ruledlab-embed.js';

/**
 * The parameters of an exercise in H5P (content/content.json, set by semantics.json's fields).
 * @typedef {object} H5PParams
 * @property {string} exercise   a built-in exercise's id, or an exercise as JSON
 * @property {string[]} [more]   further exercises: a problem set, one activity, the score their sum
 * @property {string} [title]    the activity's title, shown above the exercise
 * @property {'auto' | 'en' | 'de'} [language]
 * @property {number} [height]    CSS pixels
 * @property {{controls?: boolean, text?: boolean, edit?: boolean, leave?: boolean, solution?: string}} [readers]
 *   `solution`: "never", or after how many checks that do not solve it ("1": the default)
 * @property {'attempt' | 'learner'} [draw]   numbers drawn per attempt (the default) or per learner
 */

/** library.json of the content type. */
export function libraryJson() {
  return {
    title: 'ruledlab exercise',
    description:
      'An exercise on discrete ruled surfaces and line congruences, drawn in 3D and checked by ruledlab’s geometry core.',
    machineName: H5P_LIBRARY,
    majorVersion: H5P_MAJOR,
    minorVersion: H5P_MINOR,
    patchVersion: H5P_PATCH,
    runnable: 1,
    license: 'MIT',
    author: 'ruledlab',
    embedTypes: ['iframe'],
    // (H5P core 1.19 has every call it uses: xAPI events, scored results, saved state)
    coreApi: { majorVersion: 1, minorVersion: 19 },
    preloadedJs: [{ path: H5P_SCRIPT }],
  };
}

/** The editor's fields (semantics.json), in English; `de` gives the German labels (language/de.json). */
export function semanticsJson(lang = 'en') {
  const de = lang === 'de';
  const w = (/** @type {string} */ en, /** @type {string} */ german) => (de ? german : en);
  return [
    {
      name: 'exercise',
      type: 'text',
      widget: 'textarea',
      label: w('Exercise', 'Aufgabe'),
      description: w(
        'A built-in exercise’s id (e.g. torsal-pair), or an exercise as JSON: ruledlab’s page writes it (Share → Make an exercise from this view); the format is in ruledlab’s book, “Exercises”.',
        'Die Kennung einer eingebauten Aufgabe (z. B. torsal-pair) oder eine Aufgabe als JSON: ruledlabs Seite schreibt sie (Teilen → Aus dieser Ansicht eine Aufgabe machen); das Format steht in ruledlabs Buch, „Aufgaben“.',
      ),
      maxLength: MAX_TASK,
    },
    {
      name: 'more',
      type: 'list',
      label: w('More exercises (a problem set)', 'Weitere Aufgaben (ein Aufgabenblatt)'),
      description: w(
        'One activity, its score the sum of the exercises’; each as the first.',
        'Eine Aktivität, ihre Punkte die Summe der Aufgaben; jede wie die erste.',
      ),
      entity: w('exercise', 'Aufgabe'),
      min: 0,
      max: MAX_PACKAGE_TASKS - 1,
      optional: true,
      field: {
        name: 'exercise',
        type: 'text',
        widget: 'textarea',
        label: w('Exercise', 'Aufgabe'),
        maxLength: MAX_TASK,
      },
    },
    {
      name: 'title',
      type: 'text',
      label: w('Title shown above it', 'Titel darüber'),
      optional: true,
      maxLength: MAX_TASK_TITLE,
    },
    {
      name: 'language',
      type: 'select',
      label: w('Language', 'Sprache'),
      options: [
        { value: 'auto', label: w('the page’s', 'die der Seite') },
        { value: 'en', label: 'English' },
        { value: 'de', label: 'Deutsch' },
      ],
      default: 'auto',
    },
    {
      name: 'height',
      type: 'number',
      label: w('Height (pixels)', 'Höhe (Pixel)'),
      min: 240,
      max: 2000,
      default: H5P_HEIGHT,
    },
    {
      name: 'readers',
      type: 'group',
      label: w('What students may do', 'Was Studierende dürfen'),
      fields: [
        { name: 'controls', type: 'boolean', label: w('See the controls', 'Die Bedienelemente sehen'), default: true },
        { name: 'text', type: 'boolean', label: w('See the explanation', 'Die Erklärung sehen'), default: false },
        { name: 'edit', type: 'boolean', label: w('Drag the points', 'Die Punkte ziehen'), default: true },
        { name: 'leave', type: 'boolean', label: w('Leave the exercise', 'Die Aufgabe verlassen'), default: false },
        {
          name: 'solution',
          type: 'select',
          label: w('The solution may be shown', 'Die Lösung darf gezeigt werden'),
          description: w(
            'A solution shown earns nothing, nor does a check after it.',
            'Eine gezeigte Lösung bringt nichts ein, eine Prüfung danach auch nicht.',
          ),
          options: [
            ...[0, 1, 2, 3, 5]
              .filter((n) => n <= MAX_SOLUTION_AFTER)
              .map((n) => ({
                value: String(n),
                label:
                  n === 0
                    ? w('at once', 'sofort')
                    : w(
                        `after ${n} ${n === 1 ? 'check' : 'checks'} without solving it`,
                        `nach ${n} ${n === 1 ? 'Prüfung' : 'Prüfungen'} ohne Lösung`,
                      ),
              })),
            { value: 'never', label: w('never', 'nie') },
          ],
          default: '1',
        },
      ],
    },
    {
      name: 'draw',
      type: 'select',
      label: w('Numbers drawn', 'Gezogene Zahlen'),
      options: [
        { value: 'attempt', label: w('per attempt', 'für jeden Versuch neu') },
        {
          value: 'learner',
          label: w('per learner (the same at every launch)', 'für jede Person fest (bei jedem Start dieselben)'),
        },
      ],
      default: 'attempt',
    },
  ];
}

/** language/de.json: the German labels and descriptions of the editor's fields, in semantics.json's shape. */
function germanSemantics() {
  /** @param {any} field @returns {any} */
  const labels = (field) => ({
    label: field.label,
    ...(field.description ? { description: field.description } : {}),
    ...(field.options ? { options: field.options.map((/** @type {any} */ o) => ({ label: o.label })) } : {}),
    ...(field.fields ? { fields: field.fields.map(labels) } : {}),
  });
  return { semantics: semanticsJson('de').map(labels) };
}

/**
 * @typedef {object} H5POptions
 * @property {string} [title]    the activity's title (default: the first exercise's, and how many more)
 * @property {string} [lang]
 * @property {number} [height]
 * @property {import('./scorm-package.js').Readers} [readers]
 * @property {'attempt' | 'learner'} [draw]
 */

/**
 * The parameters of exercises for H5P (what an .h5p's content.json holds).
 * @param {import('../task/format.js').Task | import('../task/format.js').Task[]} tasks
 * @param {H5POptions} [options]
 * @returns {H5PParams}
 */
export function h5pParams(tasks, options = {}) {
  const list = Array.isArray(tasks) ? tasks : [tasks];
  const write = (/** @type {import('../task/format.js').Task} */ t) => (builtInTask(t.id) ? t.id : writeTask(t));
  const r = options.readers ?? {};
  return {
    exercise: write(list[0]),
    ...(list.length > 1 ? { more: list.slice(1).map(write) } : {}),
    ...(options.title?.trim() ? { title: options.title.trim() } : {}),
    language: options.lang === 'en' || options.lang === 'de' ? options.lang : 'auto',
    height: options.height ?? H5P_HEIGHT,
    readers: {
      controls: r.controls ?? true,
      text: r.text ?? false,
      edit: r.edit ?? true,
      leave: r.leave ?? false,
      solution: r.solution === undefined ? '1' : r.solution === null ? 'never' : String(r.solution),
    },
    draw: options.draw === 'learner' ? 'learner' : 'attempt',
  };
}

/** The embed script: given, or fetched next to this module (a browser with the package served). */
async function embedScript(/** @type {string | Uint8Array | undefined} */ script) {
  if (typeof script === 'string') return script;
  if (script instanceof Uint8Array) return new TextDecoder().decode(script);
  const url = new URL('../../dist/ruledlab-embed.js', import.meta.url);
  if (url.protocol === 'file:') throw new PackageError('course.error.noScript');
  const response = await fetch(url);
  if (!response.ok) throw new PackageError('course.error.noScript');
  return response.text();
}

/**
 * An .h5p file of one exercise, or of several as one activity (a problem set, the score their
 * sum): its bytes. Throws a TaskError for an exercise that cannot be read, a PackageError for
 * the rest.
 * @param {string | object | Array<string | object>} tasks   built-in ids, or exercises (JSON texts or objects)
 * @param {H5POptions & {script?: string | Uint8Array}} [options]
 *   `script`: the embed script (dist/ruledlab-embed.js); fetched next to this module in a browser when not given
 * @returns {Promise<Uint8Array>}
 */
export async function h5pPackage(tasks, options = {}) {
  const read = packageTasks(Array.isArray(tasks) ? tasks : [tasks]);
  const lang = options.lang === 'de' ? 'de' : 'en';
  const script = await embedScript(options.script);
  if (!script.includes('ruled-view')) throw new PackageError('course.error.noScript');
  const title = (options.title ?? '').trim() || read.map((t) => say(undrawn(t.title, t), lang)).join(' · ');
  const h5p = {
    title,
    language: options.lang === 'en' || options.lang === 'de' ? options.lang : 'und',
    mainLibrary: H5P_LIBRARY,
    embedTypes: ['iframe'],
    license: 'U',
    defaultLanguage: lang,
    preloadedDependencies: [{ machineName: H5P_LIBRARY, majorVersion: H5P_MAJOR, minorVersion: H5P_MINOR }],
  };
  const json = (/** @type {unknown} */ x) => `${JSON.stringify(x, null, 2)}\n`;
  return makeZip({
    'h5p.json': json(h5p),
    'content/content.json': json(h5pParams(read, options)),
    [`${H5P_FOLDER}/library.json`]: json(libraryJson()),
    [`${H5P_FOLDER}/semantics.json`]: json(semanticsJson()),
    [`${H5P_FOLDER}/language/de.json`]: json(germanSemantics()),
    [`${H5P_FOLDER}/${H5P_SCRIPT}`]: script,
  });
}

/**
 * The exercises and parameters of an .h5p file made here (to check one, or to open it again;
 * `task` is the first); throws a PackageError or a TaskError.
 * @param {Uint8Array} bytes
 */
export function readH5p(bytes) {
  const files = readZip(bytes);
  for (const name of ['h5p.json', 'content/content.json'])
    if (!files[name]) throw new PackageError('course.error.missing', { name });
  let h5p;
  let params;
  try {
    h5p = JSON.parse(text(files['h5p.json']));
    params = JSON.parse(text(files['content/content.json']));
  } catch (e) {
    throw new PackageError('course.error.notH5p', { detail: String(/** @type {Error} */ (e)?.message).slice(0, 120) });
  }
  if (h5p?.mainLibrary !== H5P_LIBRARY) throw new PackageError('course.error.notH5p', { detail: 'mainLibrary' });
  const tasks = h5pExercises(params);
  return { task: tasks[0], tasks, params: /** @type {H5PParams} */ (params) };
}
