// A SCORM package made here, read back: its standard (from the manifest), the launch file the
// manifest names (as a course system finds it: the default organization's item, its resource's
// href) and the exercises of that page's state block. What is not such a package — not a zip,
// too large, no manifest, a launch file that is not ruledlab's page, exercises that cannot be
// read — is refused with a PackageError or a TaskError.
import { PackageError, readZip, text } from './zip.js';
import { packageTasks } from './scorm-package.js';
import { STATE_ID } from './page-file.js';

/** An attribute of the first element `tag` whose attribute `key` is `value` (or the first `tag`). */
function attribute(
  /** @type {string} */ xml,
  /** @type {string} */ tag,
  /** @type {string} */ want,
  /** @type {[string, string] | null} */ where = null,
) {
  for (const m of xml.matchAll(new RegExp(`<(?:\\w+:)?${tag}\\b([^>]*)>`, 'g'))) {
    const attrs = Object.fromEntries([...m[1].matchAll(/([\w:]+)\s*=\s*"([^"]*)"/g)].map((a) => [a[1], a[2]]));
    if (!where || attrs[where[0]] === where[1]) return attrs[want] ?? null;
  }
  return null;
}

/**
 * The standard, launch file and exercises of a SCORM package made by ruledlab.
 * @param {Uint8Array} bytes
 */
export function readScorm(bytes) {
  const files = readZip(bytes);
  const manifest = files['imsmanifest.xml'];
  if (!manifest) throw new PackageError('course.error.missing', { name: 'imsmanifest.xml' });
  const xml = text(manifest);
  const version = /<schemaversion>\s*([^<]*?)\s*<\/schemaversion>/.exec(xml)?.[1] ?? '';
  const standard = version === '1.2' ? 'scorm12' : /^2004/.test(version) ? 'scorm2004' : null;
  if (!standard) throw new PackageError('course.error.missing', { name: 'schemaversion' });
  // the default organization's first item, and the resource it refers to
  const org = attribute(xml, 'organizations', 'default') ?? '';
  const inOrg = xml.slice(Math.max(0, xml.indexOf(`identifier="${org}"`)));
  const item = attribute(inOrg, 'item', 'identifierref') ?? '';
  const launch = attribute(xml, 'resource', 'href', ['identifier', item]);
  if (!launch || !files[launch]) throw new PackageError('course.error.missing', { name: launch ?? 'resource href' });
  const html = text(files[launch]);
  const block = new RegExp(`<script type="application/json" id="${STATE_ID}">([\\s\\S]*?)</script>`).exec(html);
  let course;
  try {
    course = JSON.parse(block?.[1] ?? 'null')?.course;
  } catch {
    course = null;
  }
  if (!course || !Array.isArray(course.tasks)) throw new PackageError('course.error.notOneFile');
  return { standard, title: String(course.title ?? ''), launch, tasks: packageTasks(course.tasks) };
}
