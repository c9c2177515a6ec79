// The type test (`npm test`, step "lint"): every ```js / ```ts snippet of the README, and every
// module script inside its ```html snippets, is written verbatim to a .ts file and compiled
// with `tsc --strict` (skipLibCheck off) against the package's declarations, resolved as a user
// resolves them: 'ruledlab' → pkg/ruledlab.d.ts, 'ruledlab/view' → www/view.d.ts (and the
// relative paths the README uses). Snippets are top-level-await modules, one file each.
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const OUT = join(ROOT, 'target', 'readme-types');
const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');

/** @type {{ line: number, code: string }[]} */
const snippets = [];
for (const m of readme.matchAll(/^```(js|ts|html)\n([\s\S]*?)^```/gm)) {
  const line = readme.slice(0, m.index).split('\n').length;
  if (m[1] === 'html') {
    for (const s of m[2].matchAll(/<script type="module">([\s\S]*?)<\/script>/g)) snippets.push({ line, code: s[1] });
  } else snippets.push({ line, code: m[2] });
}
if (snippets.length < 3) throw new Error(`README type test: only ${snippets.length} snippets found`);

rmSync(OUT, { recursive: true, force: true });
mkdirSync(OUT, { recursive: true });
// the README's relative imports ('./pkg/ruledlab.js', './www/view.js') resolve as in a clone
for (const dir of ['pkg', 'www']) symlinkSync(join(ROOT, dir), join(OUT, dir));
const files = snippets.map(({ line, code }) => {
  const file = `readme-line-${line}.ts`;
  writeFileSync(join(OUT, file), `// README.md line ${line}, verbatim\n${code}\nexport {};\n`);
  return file;
});
const config = {
  compilerOptions: {
    strict: true,
    skipLibCheck: false,
    noEmit: true,
    target: 'es2022',
    module: 'esnext',
    moduleResolution: 'bundler',
    lib: ['es2022', 'dom', 'esnext.disposable'],
    types: [],
    baseUrl: ROOT,
    paths: {
      ruledlab: ['pkg/ruledlab.d.ts'],
      'ruledlab/view': ['www/view.d.ts'],
    },
  },
  files,
};
writeFileSync(join(OUT, 'tsconfig.json'), JSON.stringify(config, null, 2));
try {
  execFileSync(join(ROOT, 'node_modules/.bin/tsc'), ['-p', join(OUT, 'tsconfig.json')], { stdio: 'inherit' });
} catch {
  console.error(`README type test: the snippets above (in ${OUT}) do not compile under tsc --strict`);
  process.exit(1);
}
console.log(`README type test: ${files.length} snippets compile under tsc --strict`);
