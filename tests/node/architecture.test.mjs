// The page's modules keep their places (ARCHITECTURE.md): no scene imports another scene (what
// two share lives in a module named for what it is: layers/, catalogue.js, …), the layers and
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

test('no scene imports another scene; layers and what is below them import no scene', () => {
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
        (m.startsWith('layers/') || m.startsWith('gl/') || m.startsWith('ui/') || m.startsWith('i18n/')) &&
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

// (sized by concept: a file is as long as its one concept needs; 800 lines is where one file
// stops being readable in one sitting)
test('no file of www/ over 800 lines', () => {
  const long = [];
  for (const m of graph().keys()) {
    const lines = readFileSync(join(WWW, m), 'utf8').split('\n').length;
    const limit = 800;
    if (lines > limit) long.push(`${m}: ${lines} lines (at most ${limit})`);
  }
  assert.deepEqual(long, []);
});

test('scenes and layers ask the core for geometry: no roots, angles or vector helpers of their own', () => {
  // the few uses that are not geometry of the paper, each with its reason
  const allowed = new Map([
    ['scenes/formula.js', 'Math.hypot of the bounding box: how far the camera stands back'],
    ['scenes/lines.js', 'Math.sin/cos: a fixed pseudo-random wiggle of the demo input, not a formula'],
    ['layers/isometry.js', "math.js's multiply: the 4×4 frame of the conoidal model, as WebGL takes it"],
  ]);
  const wrong = [];
  for (const [m, deps] of graph()) {
    if (!m.startsWith('scenes/') && !m.startsWith('layers/')) continue;
    const text = readFileSync(join(WWW, m), 'utf8');
    const uses = [
      ...text.matchAll(/Math\.(sqrt|hypot|atan2?|acos|asin|cos|sin|tan|cbrt)\b/g),
      ...(deps.includes('math.js') ? [['math.js']] : []),
    ];
    if (uses.length && !allowed.has(m)) wrong.push(`${m}: ${uses.map((u) => u[0]).join(', ')}`);
  }
  assert.deepEqual(wrong, []);
  // an allowance that is no longer needed is taken out
  for (const m of allowed.keys()) assert.ok(graph().has(m), `${m} is gone: take it off the list`);
});

test('ARCHITECTURE.md and the book’s internals name only files that exist', () => {
  const ROOT = fileURLToPath(new URL('../..', import.meta.url));
  const text = [
    'ARCHITECTURE.md',
    ...readdirSync(join(ROOT, 'docs/src/internals')).map((f) => `docs/src/internals/${f}`),
  ]
    .map((f) => readFileSync(join(ROOT, f), 'utf8'))
    .join('\n');
  // paths in backticks, and the file names of the diagrams (relative to www/ there)
  const names = new Set([
    ...[...text.matchAll(/`([\w./-]+\.(?:js|mjs|rs|md|sh|json|toml|html))`/g)].map((m) => m[1]),
    ...[...text.matchAll(/```\n([\s\S]*?)```/g)].flatMap((m) =>
      [...m[1].matchAll(/[\w./-]+\.(?:js|rs)\b/g)].map((n) => n[0]),
    ),
  ]);
  // a name may be written relative to the folder its sentence is about ("`base/lanes/`'s
  // `simd128.rs`"): it must be the end of a path of the repository
  /** @type {(dir: string) => string[]} */
  const walk = (dir) =>
    readdirSync(join(ROOT, dir)).flatMap((name) => {
      const path = dir ? `${dir}/${name}` : name;
      if (['node_modules', 'target', 'pkg', 'dist', 'site', '.git', 'corpus', 'artifacts', '.venv'].includes(name))
        return [];
      return statSync(join(ROOT, path)).isDirectory() ? walk(path) : [path];
    });
  const files = walk('');
  const missing = [...names].filter(
    (name) =>
      !name.includes('<') &&
      !/^(pkg|dist|site|target)\//.test(name) && // what the build makes
      !files.some((f) => f === name || f.endsWith(`/${name}`)),
  );
  assert.ok(names.size > 60, `only ${names.size} names found`);
  assert.deepEqual(missing, []);
});

// The parts of a stage (www/stage/*.js) draw from the state and ask for changes through the ports
// their stage gives them: none imports the stage or another part (only the stage's element
// helpers), none holds the stage. Opening (open.js) and the exercise's API (exercise-api.js) act
// for the stage and take it.
const STAGE_HELPERS = new Set(['stage/elements.js', 'stage/touch.js', 'stage/options.js']);
const ACTS_FOR_STAGE = new Set(['stage/open.js', 'stage/exercise-api.js']);

test('a part of the stage imports no stage and no other part, and holds no stage', () => {
  const g = graph();
  const parts = [...g.keys()].filter((m) => m.startsWith('stage/') && !STAGE_HELPERS.has(m) && !ACTS_FOR_STAGE.has(m));
  assert.ok(parts.length >= 8, `the parts: ${parts.join(', ')}`);
  for (const part of parts) {
    for (const dep of g.get(part) ?? [])
      assert.ok(
        dep !== 'stage.js' && (!dep.startsWith('stage/') || STAGE_HELPERS.has(dep)),
        `${part} imports ${dep}: a part asks its stage through its ports`,
      );
    const code = readFileSync(join(WWW, part), 'utf8')
      .replace(/\/\*[\s\S]*?\*\//g, '')
      .replace(/\/\/.*$/gm, '');
    assert.doesNotMatch(code, /\bstage\b|\bStage\b(?!Elements)/, `${part} names the stage in its code`);
  }
});

test('only the store writes the state: no module assigns a field of a state or replaces the store’s', () => {
  const FIELDS = 'scene|params|input|inputNote|exercise|paper|data|lang|controls|text|editable|changed|moving';
  const write = new RegExp(`\\bstate(?:\\(\\))?\\.(?:${FIELDS})\\s*(?:=(?!=)|\\+=|-=)|\\.current\\s*=(?!=)`);
  for (const m of graph().keys()) {
    if (m === 'store.js') continue;
    const code = readFileSync(join(WWW, m), 'utf8').replace(/\/\/.*$/gm, '');
    const line = code.split('\n').find((l) => write.test(l));
    assert.equal(line, undefined, `${m} writes the state: ${line?.trim()}`);
  }
});

// One name per thing. A figure is a picture (the view's, the paper's, a printed one); what two
// scenes draw alike are layers (www/layers/) and a picture beside the view a diagram
// (Built.diagram, www/diagrams/); a task is an exercise, and the browser's unit of work a turn
// (schedule.js's nextTurn); the view's frame is drawn into a framebuffer (gl/framebuffer.js), no
// longer a "frame target" beside the snap targets (the camera's target, the point it looks at,
// and the machinist's target curve keep the names their fields give them); the link's codec is
// link.js. The old names are gone from the code and the book (the deprecated exports of index.js
// and the changelog aside).
const OLD_NAMES = [
  [/www\/figures\/|'\.\.?\/figures\//, 'www/figures/ (now www/layers/)'],
  [
    /\b(?:congruence|convergence|focal|isometry|striction|subdivision|deviation)Figure\b/,
    'xFigure (now xLayers, deviationDiagram)',
  ],
  [/\bFrameTarget\b|gl\/target\.js/, 'FrameTarget, gl/target.js (now Framebuffer, gl/framebuffer.js)'],
  [/\bnextTask\b/, 'nextTask (now nextTurn)'],
  [/\bopenExercise\b|\bopenScene\b/, 'openExercise, openScene (now openView)'],
  [
    /[^\w-]state\.js\b|\breadState\b|\bwriteState\b|\bViewState\b/,
    'state.js, readState, writeState, ViewState (now link.js, readLink, writeLink, LinkState)',
  ],
  [/\bbuilt\.figure\b/, 'built.figure (now diagramOf(built))'],
];

test('the old names are gone', () => {
  const ROOT = fileURLToPath(new URL('../..', import.meta.url));
  /** @type {(dir: string) => string[]} */
  const walk = (dir) =>
    readdirSync(join(ROOT, dir)).flatMap((name) => {
      const path = `${dir}/${name}`;
      // (what a build or an install writes is not read)
      if (['build', 'dist', 'node_modules', 'target', '.venv', 'corpus', 'artifacts'].includes(name)) return [];
      if (statSync(join(ROOT, path)).isDirectory()) return walk(path);
      return /\.(js|mjs|rs|md|html|py)$/.test(name) ? [path] : [];
    });
  const files = [
    ...['www', 'src', 'crates', 'docs/src', 'tests', 'python', 'examples', 'scripts'].flatMap(walk),
    'ARCHITECTURE.md',
    'README.md',
  ];
  const found = [];
  for (const file of files) {
    if (file === 'tests/node/architecture.test.mjs' || file === 'docs/src/changelog.md') continue;
    const lines = readFileSync(join(ROOT, file), 'utf8').split('\n');
    for (const [i, line] of lines.entries()) {
      // the deprecated exports keep the old names for this release
      if (file === 'www/index.js' && /deprecated|readLink as readState|writeLink as writeState/.test(line)) continue;
      if (
        file === 'www/scene.js' &&
        /deprecated: the earlier name of `diagram`|built\.diagram \?\? built\.figure/.test(line)
      )
        continue;
      for (const [re, what] of OLD_NAMES) if (re.test(line)) found.push(`${file}:${i + 1}: ${what}`);
    }
  }
  assert.ok(files.length > 400, `only ${files.length} files read`);
  assert.deepEqual(found, []);
});
