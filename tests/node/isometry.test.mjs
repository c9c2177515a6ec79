// Section 3 through the package: bending, hinges, conoidal model, development.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab, { sampled } from './load.mjs';

const { AnalyticSurface, RuledSurface } = ruledlab;
const near = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));

/** Edge lengths of the polygon a_i + t_i (b_i − a_i), computed here in JS. */
function polygon(segments, t) {
  const p = t.map((ti, i) =>
    [0, 1, 2].map((k) => segments[6 * i + k] + ti * (segments[6 * i + 3 + k] - segments[6 * i + k])),
  );
  return p.slice(1).map((q, i) => Math.hypot(q[0] - p[i][0], q[1] - p[i][1], q[2] - p[i][2]));
}

const quartic = (n = 30) => sampled('quartic', n);

test('bend(0) is the input, bend(1) the conoidal model, and every bend is isometric', () => {
  const s = quartic();
  const input = s.segments();
  const t = Array.from({ length: s.length }, (_, i) => Math.sin(7 * i) * 1.5);
  const lengths = polygon(input, t);
  const b0 = s.bend(0).segments();
  input.forEach((x, i) => {
    assert.ok(near(x, b0[i]), `bend(0)[${i}]`);
  });
  const conoidal = s.conoidal().segments();
  const b1 = s.bend(1).segments();
  conoidal.forEach((x, i) => {
    assert.ok(near(x, b1[i]), `bend(1)[${i}]`);
  });
  for (const tb of [0.25, 0.5, 1]) {
    const bent = s.bend(tb);
    for (const [i, l] of polygon(bent.segments(), t).entries()) {
      assert.ok(near(l, lengths[i]), `t=${tb} edge ${i}: ${l} vs ${lengths[i]}`);
    }
    bent.free();
  }
});

test('conoidal rulings are all orthogonal to n_{0,1}', () => {
  const s = quartic();
  const n01 = s.invariants().centralNormal.subarray(0, 3);
  const c = s.conoidal();
  const seg = c.segments();
  for (let i = 0; i < c.length; i++) {
    const d = [0, 1, 2].map((k) => seg[6 * i + 3 + k] - seg[6 * i + k]);
    const dot = (d[0] * n01[0] + d[1] * n01[1] + d[2] * n01[2]) / Math.hypot(...d);
    assert.ok(Math.abs(dot) < 1e-12, `ruling ${i}: ${dot}`);
  }
});

test('hinge(angles) turns the hinges; hingeAngles gives N − 2 values', () => {
  const s = quartic(12);
  const tau = s.hingeAngles();
  assert.equal(tau.length, 10);
  // turning every hinge by −τ is the conoidal model
  const c1 = s.hinge(tau.map((x) => -x)).segments();
  const c2 = s.conoidal().segments();
  c1.forEach((x, i) => {
    assert.ok(near(x, c2[i]));
  });
});

test('development: 4 numbers per ruling, R_0 on the x-axis, a cone has measure 0', () => {
  const s = quartic(20);
  const dev = s.development();
  assert.equal(dev.length, 80);
  assert.deepEqual(
    [dev[0], dev[1], dev[3]].map((x) => Math.round(x * 1e12)),
    [0, 0, 0],
  );
  assert.ok(s.nonDevelopability() > 0.01);
  const cone = AnalyticSurface.byName('cone').sample(24, { uMin: 0, uMax: 4, closed: false });
  assert.ok(cone.nonDevelopability() < 1e-12, `cone measure ${cone.nonDevelopability()}`);
});

test('a cylinder is developable: parallel pairs add no height (the catalogue cylinder, 24 rulings; five parallel rulings on an arc of 1 rad), and it develops into its chords', () => {
  const cylinder = AnalyticSurface.byName('cylinder');
  const round = cylinder.sample(24);
  assert.ok(round.nonDevelopability() <= 1e-12, `cylinder measure ${round.nonDevelopability()}`);
  const arc = RuledSurface.fromSegments(
    new Float64Array(
      [0, 1, 2, 3, 4].flatMap((k) => [Math.cos(k / 4), Math.sin(k / 4), 0, Math.cos(k / 4), Math.sin(k / 4), 1]),
    ),
  );
  assert.ok(arc.nonDevelopability() <= 1e-12, `arc measure ${arc.nonDevelopability()}`);
  // ruling k at y = k · 2 sin(1/8), from x = 0 to 1
  const dev = arc.development();
  for (let k = 0; k < 5; k++) {
    const y = 2 * k * Math.sin(1 / 8);
    const at = dev.slice(4 * k, 4 * k + 4);
    assert.ok(
      [0, y, 1, y].every((x, j) => Math.abs(x - at[j]) < 1e-12),
      `ruling ${k}: ${[...at]}`,
    );
  }
  for (const o of [round, arc, cylinder]) o.free();
});

test('envelopeRadii: N − 2 radii; Fig. 5: r + p tan β = 1.4 for rulings at 45°, → 0 (as H²) for rulings orthogonal to the striction helix', () => {
  const middle = (name, n) => {
    const a = AnalyticSurface.byName(name);
    const s = a.sample(n, { uMin: 0, uMax: 9, closed: false });
    const radii = s.envelopeRadii();
    assert.equal(radii.length, n - 2);
    const r = radii[Math.floor(radii.length / 2)];
    s.free();
    a.free();
    return r;
  };
  assert.ok(Math.abs(middle('helical', 97) - 1.4) < 1e-3, `${middle('helical', 97)}`);
  const [coarse, fine] = [middle('helical-orthogonal', 25), middle('helical-orthogonal', 49)];
  assert.ok(Math.abs(fine) < 1e-2 && Math.abs(coarse / fine) > 3.5, `${coarse} ${fine}`);
});

test('bad arguments throw clear Errors and leave the surface usable', () => {
  const s = quartic(6);
  const cases = [
    [() => s.bend(-0.1), /RuledSurface.bend: t: must be a number in \[0, 1\], got -0.1/],
    [() => s.bend(1.5), /got 1.5/],
    [() => s.bend(NaN), /got NaN/],
    [() => s.bend('half'), /t must be a finite number, got a string/],
    [() => s.bend(1n), /t must be a finite number, got a bigint/],
    [() => s.bend(Infinity), /got inf/],
    [() => s.hinge(new Float64Array(3)), /need one angle per interior ruling: 4 for 6 rulings, got 3/],
    [() => s.hinge(['0', 0, 0, 0]), /angles\[0\] must be a number, got a string/],
    [() => s.hinge(new Float64Array([0, NaN, 0, 0])), /angle 1 is NaN, must be finite/],
  ];
  for (const [call, message] of cases) {
    assert.throws(call, (e) => e instanceof Error && message.test(e.message), String(message));
  }
  assert.equal(s.bend(0.5).length, 6);
});
