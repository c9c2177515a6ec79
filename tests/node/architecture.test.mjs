// The page's modules keep their places (ARCHITECTURE.md): no scene imports another scene (what
// two share lives in a module named for what it is: figures/, catalogue.js, …), the figures and
// everything below them import no scene, and the module graph has no cycle.
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
