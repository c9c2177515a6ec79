// Entry of dist/ruledlab.html: the page with the wasm and the worker inlined (the build
// supplies both through the virtual module "ruledlab:inline"), so the file needs no other
// request and works from disk and inside course systems.
import './configure.js';
import { startPage, showStartFailure } from '../../www/app.js';

startPage({ oneFile: true }).catch(showStartFailure);
