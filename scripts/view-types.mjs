// The declarations of `ruledlab/view`, generated from the JSDoc of www/ (the scene contract in
// www/scene.js, the Stage, the <ruled-view> element, …) by tsc --emitDeclarationOnly into
// pkg/view/ (pkg/view/www/index.d.ts is the entry; package.json's "./view" types point there).
// Written once, in the JavaScript: nothing here is typed by hand. The core's classes come from
// pkg/ruledlab.d.ts itself (imports of it are pointed there), so `ruledlab` and
// `ruledlab/view` share one RuledSurface type.
// Members marked @internal in the JSDoc are left out: the declarations say the API, not the
// implementation.
// Usage: node scripts/view-types.mjs
import { execFileSync } from 'node:child_process';
import { readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const OUT = join(ROOT, 'pkg', 'view');
rmSync(OUT, { recursive: true, force: true });
const tsc = join(ROOT, 'node_modules/.bin/tsc');
execFileSync(
  tsc,
  [
    '-p',
    join(ROOT, 'tsconfig.json'),
    '--noEmit',
    'false',
    '--declaration',
    '--emitDeclarationOnly',
    '--rootDir',
    ROOT,
    '--outDir',
    OUT,
  ],
  { stdio: 'inherit' },
);

/** @param {string} dir @returns {string[]} */
const walk = (dir) =>
  readdirSync(dir).flatMap((name) =>
    statSync(join(dir, name)).isDirectory() ? walk(join(dir, name)) : [join(dir, name)],
  );
/**
 * The declarations without the members whose JSDoc says @internal (tsc's --stripInternal
 * ignores JavaScript sources): the comment and the declaration after it, to the `;` that ends
 * it at bracket depth 0.
 * @param {string} text
 */
function stripInternal(text) {
  const lines = text.split('\n');
  /** @type {string[]} */
  const out = [];
  for (let i = 0; i < lines.length; i++) {
    if (!/^\s*\/\*\*/.test(lines[i])) {
      out.push(lines[i]);
      continue;
    }
    let end = i;
    while (!lines[end].includes('*/')) end++;
    const comment = lines.slice(i, end + 1);
    if (!comment.some((l) => /@internal\b/.test(l))) {
      out.push(...comment);
      i = end;
      continue;
    }
    let depth = 0;
    let k = end + 1;
    for (; k < lines.length; k++) {
      for (const c of lines[k]) depth += '{(['.includes(c) ? 1 : ')}]'.includes(c) ? -1 : 0;
      if (depth === 0 && /;\s*$/.test(lines[k])) break;
    }
    i = k;
  }
  return out.join('\n');
}

let count = 0;
for (const file of walk(OUT)) {
  if (!file.endsWith('.d.ts')) continue;
  count++;
  // pkg/view/<path>.d.ts imports "…/pkg/ruledlab.js" (and the CAM module's "…/pkg/cam/ruledlab_cam.js")
  // as the source did from <path>: one level up
  const text = stripInternal(readFileSync(file, 'utf8')).replace(
    /(["'])((?:\.\.\/)+)pkg\/(ruledlab\.js|cam\/ruledlab_cam\.js)\1/g,
    (_, q, up, name) => `${q}../${up}${name}${q}`,
  );
  writeFileSync(file, text);
}
const entry = join(OUT, 'www', 'index.d.ts');
if (!statSync(entry, { throwIfNoEntry: false }))
  throw new Error(`view-types: ${relative(ROOT, entry)} was not generated`);
// what JSDoc cannot say: importing ruledlab/view defines the element (document.createElement
// and querySelector know its type)
// and the typedefs of index.js that name a type of another module re-export that type itself,
// so the reference shows it with its documentation
/** @param {string} file */
const reexported = (file) =>
  readFileSync(file, 'utf8').replace(
    /^export type (\w+) = import\("([^"]+)"\)\.\1;$/gm,
    'export type { $1 } from "$2";',
  );
const aliases = reexported(entry);
// (ruledlab/course, the second entry, the same way)
const course = join(OUT, 'www', 'course', 'index.d.ts');
writeFileSync(course, reexported(course));
writeFileSync(
  entry,
  `${aliases}
declare global {
    interface HTMLElementTagNameMap {
        "ruled-view": import("./ruled-view.js").RuledView;
    }
}
`,
);
console.log(`view-types: ${count} declaration files in ${relative(ROOT, OUT)}/, entry ${relative(ROOT, entry)}`);
