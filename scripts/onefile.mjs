// Builds the one-file versions into dist/ (after scripts/build.sh has built pkg/):
//   dist/ruledlab-embed.js  one classic script defining <ruled-view>, the wasm and the worker
//                           inlined (scripts/onefile/entry.js)
//   dist/ruledlab.html      the whole page in one file: the same script inline (the wasm and
//                           the worker beside it in data blocks, read when needed:
//                           scripts/onefile/blocks.js), the CSS, a state block; no other request; works from file:// and uploaded to
//                           a course system. Its body is the page's shell (page/shell.js: the
//                           header, the linked scene's heading, chosen by a few inline lines
//                           before the first paint) and the script, a module at the end of the
//                           body: the browser paints the shell before it runs it
// The page's Content-Security-Policy allows exactly its inline script and style by hash,
// 'wasm-unsafe-eval' for the module, data:/blob: images and blob: workers.
import { build, transform } from 'esbuild';
import { createHash } from 'node:crypto';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { SCRIPT_ID, STATE_ID, stateJson } from '../www/page/onefile.js';
import { shellHtml, firstScript } from '../www/page/shell.js';
import { CSS } from '../www/ui/css.js';
import { BLOCKS, placeholder } from './onefile/blocks.js';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
/** @param {string} p */
const path = (p) => `${ROOT}${p}`;

// hex, not base64: a fifth less once compressed (scripts/onefile/hex.js)
const wasm = readFileSync(path('pkg/ruledlab_bg.wasm')).toString('hex');
const camWasm = readFileSync(path('pkg/cam/ruledlab_cam_bg.wasm')).toString('hex');
// the page's shell and the few lines that choose what the link asks for, before the first paint
const first = (await transform(firstScript(), { minify: true, target: 'es2020', legalComments: 'none' })).code.trim();
const body = shellHtml();
// a classic worker: module workers from blob: URLs do not start in file:// pages
const worker = await bundle('www/worker.js', 'iife', null, 'self.location.href');
/** @type {import('esbuild').Plugin} */
const inline = {
  name: 'ruledlab-inline',
  setup(b) {
    b.onResolve({ filter: /^ruledlab:inline$/ }, () => ({ path: 'inline', namespace: 'ruledlab' }));
    // the big texts as placeholders: the page carries them in data blocks, the embed script in place
    b.onLoad({ filter: /.*/, namespace: 'ruledlab' }, () => ({
      contents: `${Object.entries(BLOCKS)
        .map(([name, id]) => `export const ${name} = ${JSON.stringify(placeholder(id))};`)
        .join('\n')}\nexport const SHELL = ${JSON.stringify(body)};`,
      loader: 'js',
    }));
  },
};

/**
 * One bundled, minified script (text).
 * @param {string} entry @param {import('esbuild').Format} format
 * @param {import('esbuild').Plugin | null} plugin @param {string} [base]
 */
async function bundle(entry, format, plugin, base = 'document.baseURI') {
  const out = await build({
    entryPoints: [path(entry)],
    bundle: true,
    format,
    minify: true,
    write: false,
    target: 'es2022',
    legalComments: 'none',
    logLevel: 'error',
    plugins: plugin ? [plugin] : [],
    // core.js and pkg/ruledlab.js look for files next to themselves only when not configured
    ...(format === 'iife' ? { define: { 'import.meta.url': base } } : {}),
  });
  return out.outputFiles[0].text;
}

/** @param {string} text */
const sha = (text) => `'sha256-${createHash('sha256').update(text, 'utf8').digest('base64')}'`;
// one script for both: the page's with placeholders, the embed script with the texts in their place
const script = await bundle('scripts/onefile/entry.js', 'iife', inline);
/** The texts of the data blocks, by id. @type {Record<string, string>} */
const texts = { [BLOCKS.WASM]: wasm, [BLOCKS.CAM_WASM]: camWasm, [BLOCKS.WORKER]: worker };
let embed = script;
for (const [id, text] of Object.entries(texts)) {
  const literal = JSON.stringify(placeholder(id));
  if (!script.includes(literal)) throw new Error(`onefile: the script lacks the placeholder ${literal}`);
  embed = embed.replaceAll(literal, JSON.stringify(text));
}
const unfilled = embed.match(new RegExp(`["'\`]${placeholder('')}[a-z-]+["'\`]`));
if (unfilled) throw new Error(`onefile: a placeholder the build does not fill: ${unfilled[0]}`);
const page = script.replaceAll('</script', '<\\/script');
// beside the script: data blocks, never run (no CSP hash), read when needed (the hex has no "<")
const blocks = Object.entries(texts)
  .map(([id, text]) => `<script type="text/plain" id="${id}">${text.replaceAll('</script', '<\\/script')}</script>`)
  .join('\n');
// the page's styles and the view's (the page then need not adopt them): the shell is painted styled
const css = `${readFileSync(path('www/page/style.css'), 'utf8')}${CSS}`;
// scripts off (an iframe sandbox without allow-scripts): the <noscript> sentence, no endless "Loading"
const noscript = readFileSync(path('www/page/noscript.css'), 'utf8');
const icon = `data:image/svg+xml,${encodeURIComponent(readFileSync(path('www/favicon.svg'), 'utf8'))}`;
const csp = [
  "default-src 'none'",
  `script-src ${sha(first)} ${sha(page)} 'wasm-unsafe-eval'`,
  `style-src ${sha(css)} ${sha(noscript)}`,
  'img-src data: blob:',
  'worker-src blob:',
  "connect-src 'none'",
  "object-src 'none'",
  "base-uri 'none'",
  "form-action 'none'",
].join('; ');
const html = `<!doctype html>
<html lang="en" data-build="onefile" data-shell>
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="${csp}">
<title>ruledlab · discrete ruled surfaces and line congruences</title>
<link rel="icon" href="${icon}">
<style>${css}</style>
<noscript><style>${noscript}</style></noscript>
<script type="application/json" id="${STATE_ID}">${stateJson('')}</script>
<script>${first}</script>
</head>
<body>${body}
${blocks}
<script type="module" id="${SCRIPT_ID}">${page}</script></body>
</html>
`;
mkdirSync(path('dist'), { recursive: true });
writeFileSync(path('dist/ruledlab.html'), html);
writeFileSync(path('dist/ruledlab-embed.js'), embed);
// what the build made, for the served page's Share dialog (is the embed script here?)
writeFileSync(
  path('dist/manifest.json'),
  `${JSON.stringify({ embed: 'ruledlab-embed.js', page: 'ruledlab.html' }, null, 2)}\n`,
);
/** @param {number} n */
const kib = (n) => `${(n / 1024).toFixed(0)} KiB`;
console.log(
  `build: dist/ruledlab.html ${kib(html.length)}, ${kib(gzipSync(html).length)} gzipped; dist/ruledlab-embed.js ${kib(embed.length)}, ${kib(gzipSync(embed).length)} gzipped`,
);
