// The one script of the one-file build, with the wasm and the worker inlined (the build supplies
// both through the virtual module "ruledlab:inline"). It is dist/ruledlab-embed.js, which
// defines <ruled-view> on any page, and the inline script of dist/ruledlab.html, which also
// starts the page there (the file's state block marks it). One script for both, so the one-file
// page can hand out the exact embed script it runs (Share → "Download ruledlab-embed.js"). In an
// H5P activity it is the content type's viewer and registers it.
import './configure.js';
import '../../www/index.js';
import { startPage, showStartFailure } from '../../www/page/app.js';
import { isOneFilePage, SCRIPT_ID } from '../../www/page/onefile.js';
import { registerContentType } from '../../www/course/h5p-type.js';
import { standalone } from './blocks.js';

// the text of this script when it is inline (the one-file page, where it is a module at the end
// of the body: currentScript is null there), read while it runs; it hands out the embed script,
// which carries the data blocks' texts in place of their placeholders (blocks.js)
const source = (document.currentScript ?? document.getElementById(SCRIPT_ID))?.textContent ?? '';

// in an H5P activity (this script is the H5P.RuledlabExercise library's viewer: course/h5p-package.js)
const h5p = /** @type {any} */ (globalThis).H5P;
if (h5p?.EventDispatcher) registerContentType(h5p);

if (isOneFilePage(document)) {
  const go = () => startPage({ oneFile: true, embedScript: () => standalone(source) }).catch(showStartFailure);
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', go, { once: true });
  else go();
}
