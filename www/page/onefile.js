// The view as one HTML file, for a course page: the one-file build (dist/ruledlab.html) with
// the current state written into its state block, which the file reads when it is opened
// without a hash (from disk). The state block is JSON, never executed, so the file's
// Content-Security-Policy hash of its script stays valid (the block: course/page-file.js).
import { STATE_ID, stateBlock, withState } from '../course/page-file.js';

export { STATE_ID, stateJson, withState } from '../course/page-file.js';

/** The body of the one-file build before its script runs. */
export const BODY =
  '<p id="boot" class="boot">Loading ruledlab …</p>' +
  '<noscript><p class="boot boot-problem" lang="en">ruledlab needs JavaScript, which is turned off here (a page that shows it in a frame may have turned it off: an iframe sandbox without allow-scripts). <span lang="de">ruledlab braucht JavaScript, das hier ausgeschaltet ist (eine Seite, die es in einem Rahmen zeigt, hat es vielleicht ausgeschaltet: ein iframe-sandbox ohne allow-scripts).</span></p></noscript>';

/** The body the one-file page writes into a copy of itself (its shell: scripts/onefile.mjs sets it). */
let body = BODY;

/** Sets the body of the one-file page's copies (the build's shell, scripts/onefile/configure.js). */
export function useBody(/** @type {string} */ html) {
  body = html;
}

/** The data blocks the one-file page carries beside its script, as written (scripts/onefile/blocks.js). */
let blocks = '';

/** Sets the data blocks of the one-file page's copies (scripts/onefile/configure.js). */
export function useBlocks(/** @type {string} */ html) {
  blocks = html;
}

/** The id of the page's script (at the end of its body: what is above it is painted first). */
export const SCRIPT_ID = 'ruledlab-script';

/** The one-file page's script element as it was written, taken while it runs (the page then replaces the body). */
const SCRIPT = typeof document === 'undefined' ? '' : (document.getElementById(SCRIPT_ID)?.outerHTML ?? '');
/** … and its head, before the page changes it (its title, the styles adopted). */
const HEAD = typeof document === 'undefined' ? '' : document.head.innerHTML;

/** Whether `doc` is the one-file page (dist/ruledlab.html or a view downloaded from it). */
export function isOneFilePage(/** @type {Document} */ doc) {
  return doc.documentElement.dataset.build === 'onefile' && doc.getElementById(STATE_ID) !== null;
}

/** The hash stored in the page's state block, if any. */
export function storedHash() {
  const { hash } = stateBlock(document);
  return typeof hash === 'string' ? hash : '';
}

/** What the state block says of a SCORM package (page/course.js reads it), or null. */
export function storedCourse() {
  return stateBlock(document).course ?? null;
}

/**
 * The one-file build as written: this document itself when it is the one-file build (its state
 * block as the file came), otherwise dist/ruledlab.html fetched from the server (throws when it
 * is not there).
 * @param {boolean} oneFile
 */
export async function oneFileHtml(oneFile) {
  if (oneFile)
    return `<!doctype html>\n<html lang="en" data-build="onefile" data-shell>\n<head>${HEAD}</head>\n<body>${body}\n${blocks ? `${blocks}\n` : ''}${SCRIPT}</body>\n</html>\n`;
  const response = await fetch(new URL('../../dist/ruledlab.html', import.meta.url));
  if (!response.ok) throw new Error(`dist/ruledlab.html: HTTP ${response.status}`);
  return response.text();
}

/**
 * The one-file build showing `hash` (see oneFileHtml).
 * @param {boolean} oneFile
 * @param {string} hash
 */
export async function oneFileWithState(oneFile, hash) {
  return withState(await oneFileHtml(oneFile), hash);
}
