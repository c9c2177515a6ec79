// The book's sizes are the build's: docs/src/internals/sizes.md's table, written by
// `node scripts/sizes.mjs --write`, against what scripts/sizes.mjs measures in pkg/ and dist/ now
// (within 1 KiB), every measured thing in it; and each module within its limit.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { LIMITS_KIB, measureBuild, readTable } from '../../scripts/sizes.mjs';

const book = readFileSync(new URL('../../docs/src/internals/sizes.md', import.meta.url), 'utf8');
const sizes = measureBuild();

test('the book’s table of sizes is the build’s, within 1 KiB', () => {
  const rows = readTable(book);
  assert.deepEqual(
    rows.map((r) => r.what),
    sizes.map((s) => s.what),
    'every measured thing has its row (node scripts/sizes.mjs --write)',
  );
  for (const [i, s] of sizes.entries()) {
    const measured = [s.raw, s.gzip, s.brotli].map((n) => n / 1024);
    for (const [j, n] of rows[i].kib.entries())
      assert.ok(
        Math.abs(n - measured[j]) <= 1,
        `${s.what}: the book says ${n} KiB, the build ${measured[j].toFixed(1)} KiB (node scripts/sizes.mjs --write)`,
      );
  }
});

test('each wasm module within its limit', () => {
  for (const [key, limit] of Object.entries(LIMITS_KIB)) {
    const s = sizes.find((x) => x.key === key);
    assert.ok(s, `${key} measured`);
    assert.ok(s.gzip <= limit * 1024, `${s.what}: ${(s.gzip / 1024).toFixed(1)} KiB gzipped, over ${limit} KiB`);
  }
});
