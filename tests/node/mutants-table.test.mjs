// The book's table of mutation testing (docs/src/internals/mutation-testing.md) has a row for
// every module of the geometry crate (src/) and the CAM crate (crates/ruledlab-cam/src/) with
// code outside its tests — measured, or marked "not measured" — and no row for a file that is
// gone.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

/** The .rs files below `dir` (relative to it) with a function outside their tests. @param {string} dir */
function modules(dir) {
  /** @type {(sub: string) => string[]} */
  const walk = (sub) =>
    readdirSync(join(ROOT, dir, sub)).flatMap((name) => {
      const path = sub ? `${sub}/${name}` : name;
      if (statSync(join(ROOT, dir, path)).isDirectory()) return walk(path);
      return name.endsWith('.rs') && !['tests.rs', 'fixtures.rs'].includes(name) ? [path] : [];
    });
  return walk('').filter((path) => {
    const code = readFileSync(join(ROOT, dir, path), 'utf8').split(/#\[cfg\(test\)\]\s*\n\s*(?:pub )?mod /)[0];
    return /\bfn /.test(code);
  });
}

test('every module of both crates has its row in the book’s mutation table, and no row names a file that is gone', () => {
  const book = readFileSync(join(ROOT, 'docs/src/internals/mutation-testing.md'), 'utf8');
  const rows = [...book.matchAll(/^\| `([^`]+)`/gm)].map((m) => m[1]);
  const want = [...modules('src'), ...modules('crates/ruledlab-cam/src').map((m) => `crates/ruledlab-cam/src/${m}`)];
  assert.ok(want.length > 80, `only ${want.length} modules found`);
  assert.deepEqual(
    want.filter((m) => !rows.includes(m)),
    [],
    'modules without a row (measure them, or add them as not measured)',
  );
  assert.deepEqual(
    rows.filter((r) => !want.includes(r)),
    [],
    'rows of files that are gone',
  );
});
