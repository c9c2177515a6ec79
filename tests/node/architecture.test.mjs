// The page's modules keep their places (ARCHITECTURE.md): no scene imports another scene (what
// two share lives in a module named for what it is: figures/, catalogue.js, …), the figures and
// everything below them import no scene, the module graph has no cycle, nothing the package
// ships (everything but www/page/) imports the page's shell, and every file stays small enough
// to read in one sitting.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const WWW = fileURLToPath(new URL('../../www/', import.meta.url));

/** Every module of www/ with the www/ modules it imports (static imports and re-exports). */
function graph() {
  /** @type {Map<string, string[]>} */
  const out = new Map();
  const walk = (dir) => {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      if (statSync(path).isDirectory()) walk(path);
      else if (name.endsWith('.js')) {
        const text = readFileSync(path, 'utf8');
        const deps = [...text.matchAll(/^(?:import|export)\s[^'"]*?from\s+'([^']+)'|^import\s+'([^']+)'/gm)]
          .map((m) => m[1] ?? m[2])
          .filter((spec) => spec.startsWith('.'))
          .map((spec) => relative(WWW, resolve(dirname(path), spec)))
          .filter((dep) => !dep.startsWith('..'));
        out.set(relative(WWW, path), deps);
      }
    }
  };
  walk(WWW);
  return out;
}

test('no scene imports another scene; figures and what is below them import no scene', () => {
  const g = graph();
  assert.ok(g.size > 40, `only ${g.size} modules`);
  const wrong = [];
  for (const [m, deps] of g) {
    for (const d of deps) {
      if (m.startsWith('scenes/') && m !== 'scenes/index.js' && d.startsWith('scenes/'))
        wrong.push(`${m} imports ${d}`);
      if (!m.startsWith('scenes/') && d.startsWith('scenes/') && d !== 'scenes/index.js')
        wrong.push(`${m} imports the scene ${d}`);
      if (
        (m.startsWith('figures/') || m.startsWith('gl/') || m.startsWith('ui/') || m.startsWith('i18n/')) &&
        d === 'scenes/index.js'
      )
        wrong.push(`${m} imports the scene list`);
    }
  }
  assert.deepEqual(wrong, []);
});

test('the page’s module graph has no cycle', () => {
  const g = graph();
  /** @type {Map<string, number>} 0 unseen, 1 on the path, 2 done */
  const state = new Map();
  const cycles = [];
  const visit = (m, path) => {
    if (state.get(m) === 2) return;
    if (state.get(m) === 1) {
      cycles.push([...path.slice(path.indexOf(m)), m].join(' → '));
      return;
    }
    state.set(m, 1);
    for (const d of g.get(m) ?? []) visit(d, [...path, m]);
    state.set(m, 2);
  };
  for (const m of g.keys()) visit(m, []);
  assert.deepEqual(cycles, []);
});

test('what ruledlab/view ships imports nothing of the page’s shell (www/page/, left out of the package)', () => {
  const wrong = [];
  for (const [m, deps] of graph())
    if (!m.startsWith('page/')) for (const d of deps) if (d.startsWith('page/')) wrong.push(`${m} imports ${d}`);
  assert.deepEqual(wrong, []);
  const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8'));
  assert.ok(pkg.files.includes('!www/page/'), 'package.json ships www/page/');
});

test('no file of www/ over 600 lines; the stage and its parts under 400', () => {
  const long = [];
  for (const m of graph().keys()) {
    const lines = readFileSync(join(WWW, m), 'utf8').split('\n').length;
    const limit = m === 'stage.js' || m.startsWith('stage/') ? 400 : 600;
    if (lines > limit) long.push(`${m}: ${lines} lines (at most ${limit})`);
  }
  assert.deepEqual(long, []);
});
