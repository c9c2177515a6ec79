// Zip files for course systems (a SCORM package, an .h5p file): written and read with fflate
// (pkg/zip.js, scripts/zip.mjs), in a browser or in Node. What is read is checked: a zip that is
// not one, too large, or holding names that leave its folder is refused with a PackageError.
import { strFromU8, strToU8, unzipSync, zipSync } from '../../pkg/zip.js';
import { MAX_PACKAGE_BYTES } from '../limits.js';

/** A package that cannot be made or read: its message in English, `details` for the page's language. */
export class PackageError extends Error {
  /** @param {string} reason  i18n key (course.error.*) @param {Record<string, string | number>} args */
  constructor(reason, args = {}) {
    super(
      (ENGLISH[reason] ?? reason).replace(/\{(\w+)\}/g, (/** @type {string} */ m, /** @type {string} */ k) =>
        k in args ? String(args[k]) : m,
      ),
    );
    this.name = 'PackageError';
    this.code = 'invalid-package';
    this.details = { reason, args };
  }
}

/** The English sentences of the reasons (the page says them in its language from `details`). */
const ENGLISH = /** @type {Record<string, string>} */ ({
  'course.error.notZip': 'This is not a zip file: {detail}.',
  'course.error.tooLarge': 'The package is larger than {max} MB.',
  'course.error.badName': 'The package holds a file outside its folder: "{name}".',
  'course.error.missing': 'The package lacks "{name}".',
  'course.error.noTasks': 'A package needs 1 to {max} exercises.',
  'course.error.standard': 'The standard is "scorm12" or "scorm2004", not "{standard}".',
  'course.error.notOneFile': 'The page given is not ruledlab’s one-file build (dist/ruledlab.html).',
  'course.error.noPage':
    'Give the one-file page (dist/ruledlab.html) as "page": in Node, readFileSync(require.resolve("ruledlab/ruledlab.html"), "utf8").',
  'course.error.noScript':
    'Give the embed script (dist/ruledlab-embed.js) as "script": in Node, readFileSync(require.resolve("ruledlab/embed"), "utf8").',
  'course.error.notH5p': 'This .h5p file holds no ruledlab exercise ({detail}).',
});

/** A date for every file of a package, so that the same package is the same bytes. */
const MTIME = new Date(Date.UTC(2026, 0, 1));

/**
 * A zip of `files` (name → text or bytes), deflated.
 * @param {Record<string, string | Uint8Array>} files
 */
export function makeZip(files) {
  /** @type {Record<string, Uint8Array>} */
  const bytes = {};
  for (const [name, content] of Object.entries(files))
    bytes[name] = typeof content === 'string' ? strToU8(content) : content;
  return zipSync(bytes, { level: 6, mtime: MTIME });
}

/**
 * The files of a zip (name → bytes); throws a PackageError for what is not a zip, larger than
 * MAX_PACKAGE_BYTES (packed or unpacked), or names a path outside the zip's folder.
 * @param {Uint8Array} zip
 */
export function readZip(zip) {
  const max = MAX_PACKAGE_BYTES / (1024 * 1024);
  if (!(zip instanceof Uint8Array)) throw new PackageError('course.error.notZip', { detail: 'no bytes' });
  if (zip.length > MAX_PACKAGE_BYTES) throw new PackageError('course.error.tooLarge', { max });
  let total = 0;
  /** @type {Record<string, Uint8Array>} */
  let files;
  try {
    files = unzipSync(zip, {
      filter: (f) => {
        total += f.originalSize;
        if (total > MAX_PACKAGE_BYTES) throw new PackageError('course.error.tooLarge', { max });
        return true;
      },
    });
  } catch (e) {
    if (e instanceof PackageError) throw e;
    throw new PackageError('course.error.notZip', { detail: String(/** @type {Error} */ (e)?.message).slice(0, 120) });
  }
  for (const name of Object.keys(files))
    if (name.startsWith('/') || name.split(/[\\/]/).includes('..'))
      throw new PackageError('course.error.badName', { name: name.slice(0, 120) });
  return files;
}

/** A file of a zip as text (UTF-8). */
export const text = (/** @type {Uint8Array} */ bytes) => strFromU8(bytes);
