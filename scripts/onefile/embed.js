// Entry of dist/ruledlab-embed.js: <ruled-view> in one classic script with the wasm and the
// worker inlined, for pages that cannot serve .wasm files (or set their MIME type).
import './configure.js';
import '../../www/view.js';
