// The one-file page's state block (dist/ruledlab.html, built by scripts/onefile.mjs): a JSON
// script element the page reads when it is opened without a hash — the view to show, and, in a
// SCORM package, the package's exercises (`course`). It is data, never executed, so the file's
// Content-Security-Policy hash of its script stays valid. Here, and not in www/page/, because
// the package's own builders (www/course/scorm-package.js) write it too, in Node or a browser.

/** The id of the state block. */
export const STATE_ID = 'ruledlab-state';

/**
 * What a SCORM package's page records, and which exercises it holds (page/course.js reads it).
 * @typedef {object} CourseSetup
 * @property {'scorm12' | 'scorm2004'} standard
 * @property {string} title
 * @property {Array<string | object>} tasks   built-in exercises' ids, or exercises as JSON objects
 */

/** The state block's JSON for a hash (and a package's setup), with "<" escaped so it cannot end the block. */
export function stateJson(/** @type {string} */ hash, /** @type {CourseSetup | null} */ course = null) {
  return JSON.stringify(course ? { hash, course } : { hash }).replace(/</g, '\\u003c');
}

/**
 * `html` (the one-file build) with its state block set to `hash` (and a package's `course`);
 * throws when `html` is not the one-file build.
 * @param {string} html
 * @param {string} hash
 * @param {CourseSetup | null} [course]
 */
export function withState(html, hash, course = null) {
  const block = new RegExp(`(<script type="application/json" id="${STATE_ID}">)[\\s\\S]*?(</script>)`);
  if (!block.test(html)) throw new Error('not the one-file build: no state block');
  return html.replace(block, (_, open, close) => `${open}${stateJson(hash, course)}${close}`);
}

/** The state block of `doc` as it was written (an object; {} when there is none or it is not JSON). */
export function stateBlock(/** @type {Document} */ doc) {
  try {
    const data = JSON.parse(doc.getElementById(STATE_ID)?.textContent || '{}');
    return typeof data === 'object' && data !== null && !Array.isArray(data) ? data : {};
  } catch {
    return {};
  }
}
