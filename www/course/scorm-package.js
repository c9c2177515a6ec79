// A SCORM package of exercises, which every course system imports (Moodle, Canvas, ILIAS,
// Blackboard, OpenOLAT): one zip with the manifest (imsmanifest.xml), the schema files it names
// (xsi:schemaLocation; pkg/scorm-schemas.js) and the one-file page (dist/ruledlab.html) as its
// launch file, set to the exercises in its state block — nothing is fetched from elsewhere. In the course system the page finds the runtime the standard way and
// records score, status, one interaction per condition, the time and the attempt
// (www/page/scorm.js). SCORM 1.2 or SCORM 2004 4th edition; several exercises make one graded
// activity, the score their sum. Made in the browser (Share, the author) or by a program:
//   import { scormPackage } from 'ruledlab/course';
//   const zip = await scormPackage(['torsal-pair'], { standard: 'scorm2004', page: html });
import { builtInTask } from '../task/builtin.js';
import { readTask, say, TaskError, taskLink, writeTask } from '../task/format.js';
import { MAX_PACKAGE_TASKS, MAX_TASK_ID } from '../limits.js';
import { withState } from './page-file.js';
import { undrawn } from '../task/draw.js';
import { makeZip, PackageError } from './zip.js';
import { writeSolutionRule } from '../task/solution-rule.js';

/**
 * @typedef {import('../task/format.js').Task} Task
 *
 * What readers may do in a package's page (Share's options; all but `leave` by default).
 * @typedef {object} Readers
 * @property {boolean} [controls]   see the controls and the readout
 * @property {boolean} [text]       see the scene's explanation
 * @property {boolean} [edit]       drag the points of a scene that has them
 * @property {boolean} [leave]      leave the exercise for the scene alone
 * @property {number | null} [solution]   have the solution shown after this many checks that do
 *   not solve the exercise (null: never; default 1); a solution shown earns nothing either way
 *
 * @typedef {object} ScormOptions
 * @property {'scorm12' | 'scorm2004'} [standard]   SCORM 1.2 (default) or SCORM 2004 4th edition
 * @property {string} [title]      the activity's title in the course (default: the exercises' titles)
 * @property {string} [lang]       the page's language ("en", "de"; default: the reader's browser)
 * @property {string | Uint8Array} [page]   the one-file page (dist/ruledlab.html); fetched next to
 *   this module in a browser when not given (in Node: give it)
 * @property {Readers} [readers]
 * @property {'attempt' | 'learner'} [draw]   numbers drawn per attempt (the default) or per learner
 *   (from her id in the course system: the same at every launch of hers)
 */

/** The launch file of a package. */
export const LAUNCH = 'index.html';

/**
 * Exercises read for a package: built-in ids, exercise JSON (a text or an object), or Tasks;
 * throws a TaskError (code "invalid-task") or a PackageError (code "invalid-package").
 * @param {Array<string | object>} tasks
 * @returns {Task[]}
 */
export function packageTasks(tasks) {
  if (!Array.isArray(tasks) || tasks.length < 1 || tasks.length > MAX_PACKAGE_TASKS)
    throw new PackageError('course.error.noTasks', { max: MAX_PACKAGE_TASKS });
  return tasks.map((t) => {
    if (typeof t === 'string' && !t.trimStart().startsWith('{')) {
      const task = builtInTask(t);
      if (!task) throw new TaskError('task.error.unknownBuiltIn', { id: t.slice(0, MAX_TASK_ID) });
      return task;
    }
    // a Task (read already: no "ruledlab" key) is read again from its JSON, so that it is checked here too
    return typeof t === 'object' && t !== null && !('ruledlab' in t)
      ? readTask(JSON.parse(writeTask(/** @type {Task} */ (t))))
      : readTask(t);
  });
}

/** Text for XML content or an attribute value. */
export const xml = (/** @type {string} */ s) =>
  s
    .replace(/&/g, '&amp;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;')
    .replace(/"/g, '&quot;')
    // biome-ignore lint/suspicious/noControlCharactersInRegex: characters XML 1.0 does not allow
    .replace(/[\u0000-\u0008\u000b\u000c\u000e-\u001f]/g, '');

/**
 * The manifest of a package: one organization, one item, one SCO (the launch file). SCORM 1.2's
 * names (imscp_rootv1p1p2, adlcp:scormtype) or SCORM 2004 4th edition's (imscp_v1p1, adlcp_v1p3,
 * adlcp:scormType).
 * @param {{standard: 'scorm12' | 'scorm2004', id: string, title: string, launch?: string}} options
 */
export function scormManifest({ standard, id, title, launch = LAUNCH }) {
  const t = xml(title);
  const ident = `ruledlab-${id}`.replace(/[^A-Za-z0-9_.-]/g, '-');
  if (standard === 'scorm12')
    return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${ident}" version="1" xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2" xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
  </metadata>
  <organizations default="ruledlab-organization">
    <organization identifier="ruledlab-organization">
      <title>${t}</title>
      <item identifier="ruledlab-item" identifierref="ruledlab-sco" isvisible="true">
        <title>${t}</title>
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="ruledlab-sco" type="webcontent" adlcp:scormtype="sco" href="${xml(launch)}">
      <file href="${xml(launch)}"/>
    </resource>
  </resources>
</manifest>
`;
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${ident}" version="1" xmlns="http://www.imsglobal.org/xsd/imscp_v1p1" xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3" xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3" xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3" xmlns:imsss="http://www.imsglobal.org/xsd/imsss" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>2004 4th Edition</schemaversion>
  </metadata>
  <organizations default="ruledlab-organization">
    <organization identifier="ruledlab-organization">
      <title>${t}</title>
      <item identifier="ruledlab-item" identifierref="ruledlab-sco">
        <title>${t}</title>
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="ruledlab-sco" type="webcontent" adlcp:scormType="sco" href="${xml(launch)}">
      <file href="${xml(launch)}"/>
    </resource>
  </resources>
</manifest>
`;
}

/**
 * The hash a package's page opens with: in a frame (the view with what readers may see), the
 * first exercise, the language.
 * @param {Task} first
 * @param {Readers} readers
 * @param {string | undefined} lang
 */
export function packageHash(first, readers, lang) {
  const q = new URLSearchParams();
  q.set('embed', '');
  if (readers.controls ?? true) q.set('controls', '');
  if (readers.text) q.set('text', '');
  if (readers.edit ?? true) q.set('edit', '');
  if (readers.leave) q.set('leave', '');
  const rule = writeSolutionRule(readers.solution === undefined ? null : { after: readers.solution });
  if (rule) q.set('solution', rule);
  q.set(
    'task',
    taskLink(first, (id) => builtInTask(id) !== null),
  );
  if (lang) q.set('lang', lang);
  return q.toString().replace(/=(&|$)/g, '$1');
}

/** The one-file page: given, or fetched next to this module (a browser with the package served). */
export async function onePage(/** @type {string | Uint8Array | undefined} */ page) {
  if (typeof page === 'string') return page;
  if (page instanceof Uint8Array) return new TextDecoder().decode(page);
  const url = new URL('../../dist/ruledlab.html', import.meta.url);
  if (url.protocol === 'file:') throw new PackageError('course.error.noPage');
  const response = await fetch(url);
  if (!response.ok) throw new PackageError('course.error.noPage');
  return response.text();
}

/**
 * A SCORM package of `tasks` (see the module's documentation): the zip's bytes. Throws a
 * TaskError for an exercise that cannot be read, a PackageError for the rest.
 * @param {Array<string | object>} tasks   built-in ids, exercises (JSON texts or objects)
 * @param {ScormOptions} [options]
 * @returns {Promise<Uint8Array>}
 */
export async function scormPackage(tasks, options = {}) {
  const standard = options.standard ?? 'scorm12';
  if (standard !== 'scorm12' && standard !== 'scorm2004')
    throw new PackageError('course.error.standard', { standard: String(standard).slice(0, 40) });
  const read = packageTasks(tasks);
  const lang = options.lang === 'de' ? 'de' : options.lang === 'en' ? 'en' : undefined;
  const title = (options.title ?? '').trim() || read.map((t) => say(undrawn(t.title, t), lang ?? 'en')).join(' · ');
  const html = await onePage(options.page);
  if (!/data-build="onefile"/.test(html)) throw new PackageError('course.error.notOneFile');
  const course = {
    standard,
    title,
    tasks: read.map((t) => (builtInTask(t.id) ? t.id : JSON.parse(writeTask(t)))),
    ...(options.draw === 'learner' ? { draw: 'learner' } : {}),
  };
  const launch = withState(html, packageHash(read[0], options.readers ?? {}, lang), course);
  const id = read
    .map((t) => t.id)
    .join('-')
    .slice(0, 60);
  // the schema files the manifest names, beside it (as the standards ask)
  const { SCORM12_SCHEMAS, SCORM2004_SCHEMAS } = await import('../../pkg/scorm-schemas.js');
  return makeZip({
    'imsmanifest.xml': scormManifest({ standard, id, title }),
    ...(standard === 'scorm12' ? SCORM12_SCHEMAS : SCORM2004_SCHEMAS),
    [LAUNCH]: launch,
  });
}
