// No array is spread into a call in www/: an engine takes some 10⁵ arguments at most (V8 about
// 125 000), so Math.min(...values) over the distribution parameters of 10⁶ rulings throws
// RangeError ("Maximum call stack size exceeded"), which the view showed as "Something went
// wrong." with no code. The reductions and appends go through least, greatest and append
// (www/reduce.js), which loop. The guard reads every module of www/ (comments and strings left
// out) for a spread among the arguments of Math.min, Math.max, String.fromCharCode /
// fromCodePoint, push and unshift; and the data scene and its focal figure are built on more
// rulings and lines than a call takes arguments.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import ruledlab from './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { defaults, legendOf } from '../../www/scene.js';
import { translator } from '../../www/i18n/index.js';
import { append, greatest, least } from '../../www/reduce.js';

const WWW = fileURLToPath(new URL('../../www/', import.meta.url));

/** `text` with its comments and the insides of its strings and templates blanked (lengths kept). */
function code(text) {
  let out = '';
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    const two = text.slice(i, i + 2);
    let end = i + 1;
    if (two === '//') end = text.indexOf('\n', i) < 0 ? text.length : text.indexOf('\n', i);
    else if (two === '/*') end = text.indexOf('*/', i + 2) + 2 || text.length;
    else if (c === "'" || c === '"' || c === '`') {
      end = i + 1;
      while (end < text.length && text[end] !== c) end += text[end] === '\\' ? 2 : 1;
      end += 1;
      out += c + text.slice(i + 1, end - 1).replace(/[^\n]/g, ' ') + c;
      i = end;
      continue;
    } else {
      out += c;
      i = end;
      continue;
    }
    out += text.slice(i, end).replace(/[^\n]/g, ' ');
    i = end;
  }
  return out;
}

/** The calls in `text` that spread an array among their arguments: "line: callee(arguments)". */
export function spreadCalls(text) {
  const src = code(text);
  const found = [];
  for (const m of src.matchAll(
    /(Math\.(?:min|max)|String\.fromCharCode|String\.fromCodePoint|\.push|\.unshift)\s*\(/g,
  )) {
    let depth = 0;
    let spread = false;
    let k = (m.index ?? 0) + m[0].length;
    for (; k < src.length; k++) {
      const c = src[k];
      if (c === ')' && depth === 0) break;
      if ('([{'.includes(c)) depth++;
      else if (')]}'.includes(c)) depth--;
      else if (depth === 0 && src.startsWith('...', k)) spread = true;
    }
    if (spread) {
      const line = src.slice(0, m.index).split('\n').length;
      found.push(
        `${line}: ${m[1]}(${text
          .slice((m.index ?? 0) + m[0].length, k)
          .replace(/\s+/g, ' ')
          .slice(0, 60)})`,
      );
    }
  }
  return found;
}

/** Every module of www/ by its path under www/. */
function modules() {
  /** @type {string[]} */
  const out = [];
  const walk = (/** @type {string} */ dir) => {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      if (statSync(path).isDirectory()) walk(path);
      else if (/\.m?js$/.test(name)) out.push(path);
    }
  };
  walk(WWW);
  return out;
}

test('the guard finds a spread into a call, and only that', () => {
  assert.deepEqual(spreadCalls('const m = Math.min(...xs);'), ['1: Math.min(...xs)']);
  assert.deepEqual(spreadCalls('a.push(1,\n  ...b.map((x) => x));'), ['1: .push(1, ...b.map((x) => x))']);
  assert.deepEqual(spreadCalls('Math.max(0, f(...xs), [...ys].length, { ...o }.n)'), []);
  assert.deepEqual(spreadCalls('// Math.min(...xs)\nconst s = "Math.max(...ys)"; /* x.push(...z) */'), []);
  assert.deepEqual(spreadCalls('String.fromCharCode(...bytes)'), ['1: String.fromCharCode(...bytes)']);
});

test('no module of www/ spreads an array into Math.min, Math.max, fromCharCode, push or unshift', () => {
  const files = modules();
  assert.ok(files.length > 40, `only ${files.length} modules`);
  const wrong = files.flatMap((path) =>
    spreadCalls(readFileSync(path, 'utf8')).map((call) => `www/${relative(WWW, path)}:${call}`),
  );
  assert.deepEqual(wrong, [], 'use least, greatest or append from www/reduce.js');
});

test('least, greatest and append give what the spreads give, on more numbers than a call takes', () => {
  const few = [3, -1, 2.5, -0, 0];
  assert.equal(least(few), Math.min(...few));
  assert.equal(greatest(few), Math.max(...few));
  assert.equal(least([]), Infinity);
  assert.equal(greatest([]), -Infinity);
  assert.ok(Number.isNaN(least([1, NaN, 0])) && Number.isNaN(greatest([1, NaN, 0])));
  assert.equal(least([2, 3], 1), 1);
  assert.equal(greatest(new Float64Array([2, 3]), 5), 5);
  const many = Float64Array.from({ length: 1_000_000 }, (_, i) => Math.sin(i) * (1 + (i % 7)));
  assert.throws(() => Math.min(...many), RangeError, 'a spread of 10⁶ numbers (the engine takes them now?)');
  let lo = Infinity;
  let hi = -Infinity;
  for (const v of many) {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  assert.equal(least(many), lo);
  assert.equal(greatest(many), hi);
  const list = [1];
  assert.equal(append(list, many), list);
  assert.equal(list.length, 1 + many.length);
  assert.equal(list[many.length], many[many.length - 1]);
});

test('the data scene builds 300 000 rulings: invariants, striction, the smallest |δ| in its text', () => {
  const { t } = translator('en');
  const scene = SCENES.find((s) => s.id === 'data');
  assert.ok(scene);
  const n = 300_000;
  const segments = new Float64Array(6 * n);
  for (let i = 0; i < n; i++) {
    const u = (2 * Math.PI * i) / n;
    segments.set([Math.cos(u), Math.sin(u), -1, Math.cos(u + 1.2), Math.sin(u + 1.2), 1], 6 * i);
  }
  const built = scene.create(defaults(scene), { t, format: translator('en').format, lang: 'en', data: { segments } });
  assert.ok(built.layers.some((l) => l.style === 'striction'));
  // the least |δ| the text names is the core's
  const surface = ruledlab.RuledSurface.fromSegments(segments);
  const inv = surface.invariants();
  surface.free();
  let smallest = Infinity;
  for (const d of inv.distribution) if (Number.isFinite(d)) smallest = Math.min(smallest, Math.abs(d));
  assert.ok(Number.isFinite(smallest) && smallest > 0);
  assert.ok(built.description, 'a description');
});

test('the data scene shows the focal geometry of a congruence of 400 × 400 lines', () => {
  const { t, format } = translator('en');
  const scene = SCENES.find((s) => s.id === 'data');
  assert.ok(scene);
  const [rows, cols] = [400, 400];
  const segments = new Float64Array(6 * rows * cols);
  for (let i = 0; i < rows; i++)
    for (let j = 0; j < cols; j++) {
      const [x, y] = [i / (rows - 1) - 0.5, j / (cols - 1) - 0.5];
      // the normals of z = (x² − y²)/2 at its points, b = a + (−x, y, 1): real focal points
      segments.set([x, y, (x * x - y * y) / 2, x - x, y + y, (x * x - y * y) / 2 + 1], 6 * (i * cols + j));
    }
  const built = scene.create(
    { ...defaults(scene), focal: true },
    { t, format, lang: 'en', data: { segments, rows, cols } },
  );
  assert.ok(built.layers.some((l) => l.style === 'focal1'));
  assert.ok(built.readouts?.some((r) => String(r.value).includes(`/ ${rows * cols}`)));
});

test('the data scene’s level of detail: all of 20 000 rulings, editable; from 20 001 the strip through at most 2 001, at most 160 as lines, the legend as drawn', () => {
  const { t, format } = translator('en');
  const scene = SCENES.find((s) => s.id === 'data');
  assert.ok(scene);
  /** @param {number} n @param {boolean} closed */
  const build = (n, closed) => {
    const segments = new Float64Array(6 * n);
    for (let i = 0; i < n; i++) {
      const u = (2 * Math.PI * i) / n;
      segments.set([Math.cos(u), Math.sin(u), -1, Math.cos(u + 1.2), Math.sin(u + 1.2), 1], 6 * i);
    }
    const params = { ...defaults(scene), closed };
    const built = scene.create(params, { t, format, lang: 'en', data: { segments } });
    const layer = (/** @type {string} */ style) => built.layers.find((l) => l.style === style);
    return {
      built,
      lines: (layer('ruling')?.positions.length ?? 0) / 6,
      strip: (layer('strip')?.positions.length ?? 0) / 6,
      striction: (layer('striction')?.positions.length ?? 0) / 3,
      legend: legendOf(scene, params, built).map((e) => t(e.label)),
    };
  };
  const all = build(20_000, false);
  assert.equal(all.lines, 20_000);
  assert.ok(all.built.input, 'editable');
  assert.equal(all.built.note, undefined);
  assert.ok(all.legend.some((l) => /common perpendiculars/.test(l)));
  for (const n of [20_001, 21_011, 25_000]) {
    for (const closed of [false, true]) {
      const lod = build(n, closed);
      assert.equal(lod.built.input, undefined, `${n}: not editable`);
      assert.ok(lod.strip > 1_500 && lod.strip <= 2_001, `${n}: ${lod.strip} in the strip`);
      assert.ok(lod.lines > 100 && lod.lines <= 160, `${n}: ${lod.lines} lines`);
      // the striction curve through the rulings drawn (a point a pair: an open strip's curve
      // begins at its first pair and keeps its last)
      assert.ok(Math.abs(lod.striction - lod.strip) <= 1, `${n} ${closed}: ${lod.striction} of ${lod.strip}`);
      assert.deepEqual(lod.legend, ['your rulings', 'striction curve, through the rulings drawn']);
      assert.match(lod.built.note ?? '', /Level of detail: the strip and the striction curve go through one ruling in/);
      assert.equal(lod.built.readouts?.find((r) => r.label === 'readout.parallelPairs')?.value, 0);
    }
  }
});
