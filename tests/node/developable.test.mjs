// Developable strips and flat patterns through the package: the constructions keep every pair of
// rulings coplanar, the exact unfolding is an isometry (lengths checked here in JS against the 3D
// strip), a strip that overlaps itself is split, the approximate development of the hyperboloid
// leaves gaps, the exports are SVG at 1:1 in millimetres and DXF R12, errors carry stable codes,
// and a 200-ruling drag step (repair and unfolding) is timed. Strips travel as their segments
// (6 numbers per ruling).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { models } from '../../scripts/paper-models.mjs';
import { cam, sampled } from './load.mjs';

// the strips and flat patterns are the CAM module's (the module for making things)

const {
  FlatPattern,
  tangentSurface,
  coneSurface,
  cylinderSurface,
  rectifyingDevelopable,
  makeDevelopable,
  maxAbsDelta,
  maxOffPlane,
} = cam;

/** `m` points of the helix (cos u, sin u, p u), u over `turns` turns. */
function helix(m, turns, p = 0.3) {
  const out = new Float64Array(3 * m);
  for (let i = 0; i < m; i++) {
    const u = (turns * 2 * Math.PI * i) / (m - 1);
    out.set([Math.cos(u), Math.sin(u), p * u], 3 * i);
  }
  return out;
}

/** The distance between points j and k of a flat array with `d` numbers per point. */
const dist = (a, d, j, k) => Math.hypot(...Array.from({ length: d }, (_, c) => a[d * j + c] - a[d * k + c]));

/** The largest relative difference of the four edges and two diagonals of every face, pattern against strip. */
function isometry(s, pattern) {
  const p = pattern.points();
  let worst = 0;
  for (let i = 0; i + 1 < s.length / 6; i++) {
    const q = [2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2];
    for (const [j, k] of [
      [0, 1],
      [1, 2],
      [2, 3],
      [3, 0],
      [0, 2],
      [1, 3],
    ]) {
      const l3 = dist(s, 3, q[j], q[k]);
      worst = Math.max(worst, Math.abs(dist(p, 2, q[j], q[k]) - l3) / l3);
    }
  }
  return worst;
}

test('every construction is developable and unfolds isometrically', () => {
  const c = helix(41, 0.9);
  const strips = [
    tangentSurface(c, 0, 0.8),
    coneSurface(c, [0.2, -0.1, 3], 0.1, 1),
    cylinderSurface(c, [0.1, 0.2, 1], -0.4, 0.4),
    rectifyingDevelopable(c, -0.3, 0.3),
  ];
  for (const s of strips) {
    assert.equal(maxAbsDelta(s), 0);
    assert.ok(maxOffPlane(s) <= 1e-15, `an end ${maxOffPlane(s)} off its pair's plane`);
    const flat = FlatPattern.unfold(s);
    assert.equal(flat.exact, true);
    assert.ok(flat.isometryLength <= 1e-9 && flat.isometryAngle <= 1e-9);
    assert.ok(isometry(s, flat) <= 1e-9, `${isometry(s, flat)}`);
    assert.deepEqual([...flat.gaps()], new Array(s.length / 6 - 1).fill(0));
    flat.free();
  }
});

test('a dragged ruling: the repair keeps it and makes every pair coplanar again', () => {
  const seg = tangentSurface(helix(30, 1), 0.1, 1);
  seg[6 * 12 + 3] += 0.05;
  seg[6 * 12 + 5] -= 0.04;
  assert.ok(maxAbsDelta(seg) > 1e-3);
  assert.ok(maxOffPlane(seg) > 1e-3);
  const fixed = makeDevelopable(seg);
  assert.equal(maxAbsDelta(fixed), 0);
  assert.ok(maxOffPlane(fixed) <= 1e-15, `${maxOffPlane(fixed)}`);
  assert.deepEqual([...fixed.slice(72, 78)], [...seg.slice(72, 78)]);
  assert.throws(
    () => FlatPattern.unfold(seg),
    (e) =>
      e.code === 'degenerate' &&
      e.details.reason === 'not-developable' &&
      /rulings 11 and 12 are not coplanar \(an end lies .+ off the plane of the other three, more than .+; δ = /.test(
        e.message,
      ),
  );
});

test('a dragged cylinder, whose rulings meet at angles near 0, is coplanar by its ends and unfolds exactly', () => {
  // its δ computed from rounded ends is noise of order ε|d|/φ² where φ ≈ 1e-6: the core judges a
  // pair by how far an end lies off the plane of the other three
  const seg = cylinderSurface(helix(41, 0.9), [0.2, 0.1, 1], 0, 1);
  seg[6 * 20 + 3] += 0.08;
  seg[6 * 20 + 4] -= 0.05;
  const fixed = makeDevelopable(seg);
  assert.ok(maxOffPlane(fixed) <= 1e-15, `${maxOffPlane(fixed)}`);
  assert.equal(maxAbsDelta(fixed), 0);
  const flat = FlatPattern.unfold(fixed);
  assert.ok(flat.isometryLength <= 1e-9 && flat.isometryAngle <= 1e-9);
  flat.free();
});

test('a tangent surface over one and a half turns overlaps itself and is split', () => {
  const s = tangentSurface(helix(121, 1.5), 0, 1.2);
  const flat = FlatPattern.unfold(s);
  const overlaps = flat.overlaps();
  const pieces = flat.pieces();
  assert.ok(overlaps.length > 0);
  assert.ok(pieces.length >= 4, `${pieces}`);
  for (let k = 0; k < pieces.length; k += 2) {
    for (let o = 0; o < overlaps.length; o += 2)
      assert.ok(!(pieces[k] <= overlaps[o] && overlaps[o + 1] < pieces[k + 1]), `piece ${pieces[k]}…${pieces[k + 1]}`);
  }
  assert.ok(flat.segments(true).length > 0 && flat.segments().length === 6 * (3 * (s.length / 6) - 2));
  flat.free();
});

test('the hyperboloid’s approximate development leaves gaps adding up to its climb', () => {
  const s = sampled('hyperboloid', 49, { uMin: 0, uMax: 2 * Math.PI });
  const flat = FlatPattern.approximate(s.segments());
  assert.equal(flat.exact, false);
  const gaps = flat.gaps();
  const h = s.invariants().distance;
  for (const [i, g] of gaps.entries()) assert.ok(Math.abs(g - h[i]) <= 1e-12, `gap ${i}`);
  assert.ok(Math.abs(flat.climb - gaps.reduce((a, b) => a + b, 0)) <= 1e-12);
  assert.ok(Math.abs(flat.climb) > 1);
  flat.free();
  s.free();
});

test('the exports: SVG in millimetres with a check square, DXF R12 with CUT and SCORE, pages', () => {
  const s = coneSurface(helix(25, 0.8, 0.1), [0.3, 0.2, 2], 0.25, 1);
  const flat = FlatPattern.unfold(s);
  const svg = flat.svg({ scale: 60, kerf: 0.2 });
  const [, w, h] = svg.match(/width="([\d.]+)mm" height="([\d.]+)mm" viewBox="0 0 \1 \2"/) ?? [];
  assert.ok(Number(w) > 100 && Number(h) > 100, svg.slice(0, 200));
  assert.match(svg, /<rect id="check-square" [^>]*width="100" height="100"/);
  const dxf = flat.dxf({ scale: 60 });
  assert.match(dxf, /\$ACADVER\n {2}1\nAC1009/);
  for (const layer of ['CUT', 'SCORE']) assert.match(dxf, new RegExp(`LAYER\n {2}2\n${layer}\n`));
  const pages = flat.pages({ scale: 200, paper: 'letter' });
  assert.ok(pages.length > 1);
  for (const page of pages) assert.match(page, /width="215.9mm" height="279.4mm"/);
  for (const [options, option] of [
    [{ kerf: 9 }, 'kerf'],
    [{ scale: 0 }, 'scale'],
    [{ paper: 'a3' }, 'paper'],
    [{ sacle: 2 }, 'sacle'],
  ]) {
    assert.throws(
      () => flat.svg(options),
      (e) => typeof e.code === 'string' && (e.details?.option === option || e.message.includes(option)),
      option,
    );
  }
  flat.free();
});

test('the scene hands out its pattern on A4 and Letter pages: a zip of one SVG a page, the pages’ sizes in mm', async () => {
  const { SCENES } = await import('../../www/scenes/index.js');
  const { defaults } = await import('../../www/scene.js');
  const { unzipSync, strFromU8 } = await import('../../pkg/zip.js');
  const scene = /** @type {any} */ (SCENES.find((x) => x.id === 'developable'));
  const built = scene.create(
    { ...defaults(scene), kind: 'cone', n: 24 },
    { t: (/** @type {string} */ k) => k, lang: 'en' },
  );
  for (const [paper, size] of [
    ['a4', 'width="210mm" height="297mm"'],
    ['letter', 'width="215.9mm" height="279.4mm"'],
  ]) {
    const d = built.downloads.find((/** @type {any} */ x) => x.filename === `pattern-cone-${paper}.zip`);
    assert.ok(d, `a ${paper} download`);
    const blob = await d.content();
    assert.equal(blob.type, 'application/zip');
    const files = unzipSync(new Uint8Array(await blob.arrayBuffer()));
    const names = Object.keys(files);
    assert.ok(
      names.length >= 1 && names.every((n, k) => n === `page-${String(k + 1).padStart(2, '0')}.svg`),
      names.join(),
    );
    for (const n of names) assert.ok(strFromU8(files[n]).includes(size), `${paper} ${n}`);
  }
});

test('constructions refuse bad input with stable codes', () => {
  const c = helix(9, 1);
  const reason = (f) => {
    try {
      f();
    } catch (e) {
      return `${e.code}/${e.details?.reason}`;
    }
    return 'no error';
  };
  assert.equal(
    reason(() => tangentSurface(c, -1, 1)),
    'invalid-argument/span-crosses-regression',
  );
  assert.equal(
    reason(() => coneSurface(c, [c[3], c[4], c[5]], 0, 1)),
    'degenerate/apex-on-directrix',
  );
  assert.equal(
    reason(() => cylinderSurface(c, [0, 0, 0], 0, 1)),
    'invalid-argument/direction-zero',
  );
  assert.equal(
    reason(() => rectifyingDevelopable([0, 0, 0, 1, 0, 0, 2, 0, 0], 0, 1)),
    'degenerate/directrix-straight',
  );
  assert.match(
    reason(() => tangentSurface(c, 0, 'x')),
    /^invalid-argument/,
  );
});

test('a 200-ruling drag step — repair and unfolding — is timed', () => {
  const seg = tangentSurface(helix(201, 1.2), 0.05, 1);
  const steps = 40;
  const times = [];
  for (let k = 0; k < steps; k++) {
    seg[6 * 100 + 3] += 0.002;
    const t0 = performance.now();
    const fixed = makeDevelopable(seg);
    const flat = FlatPattern.unfold(fixed);
    flat.points();
    times.push(performance.now() - t0);
    assert.ok(maxOffPlane(fixed) <= 1e-15);
    flat.free();
  }
  times.sort((a, b) => a - b);
  // reported, not judged (a shared machine's clock): the median and the worst
  console.log(
    `drag step, 200 rulings: median ${times[steps >> 1].toFixed(2)} ms, worst ${times[steps - 1].toFixed(2)} ms`,
  );
});

test('the book’s printable models are what the package makes now (node scripts/paper-models.mjs remakes them)', () => {
  for (const [name, svg] of models()) {
    const path = new URL(`../../docs/src/images/paper-models/${name}`, import.meta.url);
    assert.equal(readFileSync(path, 'utf8'), svg, name);
  }
});
