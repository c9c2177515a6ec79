// What the package's "engines" says (Node.js 16.4, the first with WebAssembly SIMD) holds for what
// Node loads of it — the core (`ruledlab`), `ruledlab/cam` and `ruledlab/course`: bundled for
// node16.4, esbuild refuses newer syntax, and no API newer than 16.4 is named (building and the
// tests need Node.js 20: scripts/setup.sh says so).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { build } from 'esbuild';

const ROOT = new URL('../../', import.meta.url).pathname;
/** APIs Node.js gained after 16.4 (the version in parentheses), as the code would name them. */
const NEWER = [
  [/\bstructuredClone\(/, 'structuredClone (17)'],
  [/\bObject\.hasOwn\(/, 'Object.hasOwn (16.9)'],
  [/\.at\(-?\d/, 'Array.prototype.at (16.6)'],
  [/\.findLast(Index)?\(/, 'findLast (18)'],
  [/\.to(Sorted|Reversed|Spliced)\(/, 'change-array-by-copy (20)'],
  [/\bArray\.fromAsync\(/, 'Array.fromAsync (22)'],
  [/\bPromise\.withResolvers\(/, 'Promise.withResolvers (22)'],
  [/\bURL\.canParse\(/, 'URL.canParse (19.9)'],
  [/\bcrypto\.randomUUID\(/, 'crypto.randomUUID as a global (19)'],
];

test('the package runs on the Node.js its "engines" names: 16.4', async () => {
  const pkg = JSON.parse(readFileSync(`${ROOT}package.json`, 'utf8'));
  assert.equal(pkg.engines.node, '>=16.4');
  for (const entry of ['.', './cam', './course']) {
    const file = pkg.exports[entry].default;
    const out = await build({
      entryPoints: [`${ROOT}${file}`],
      bundle: true,
      write: false,
      format: 'esm',
      platform: 'node',
      target: 'node16.4',
      logLevel: 'silent',
      external: ['*.wasm'],
    });
    const text = out.outputFiles[0].text;
    for (const [pattern, what] of NEWER)
      assert.doesNotMatch(text, /** @type {RegExp} */ (pattern), `${entry}: ${what}`);
  }
});
