// A straightforward plain-JavaScript implementation of Section 2's invariants and of one
// four-point step of a strip, written the way one would without ruledlab: small [x, y, z]
// arrays and helper functions. It is the baseline the wasm package is measured against in
// bench/wasm.mjs (which also checks that both give the same numbers).

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);

function rulings(segments) {
  const out = [];
  for (let i = 0; i < segments.length; i += 6) {
    const a = [segments[i], segments[i + 1], segments[i + 2]];
    const b = [segments[i + 3], segments[i + 4], segments[i + 5]];
    const d = sub(b, a);
    out.push({ point: a, dir: scale(d, 1 / norm(d)) });
  }
  return out;
}

/** Angles, signed distances, δ, footpoints, striction polygon (parallel pairs not handled). */
export function invariants(segments) {
  const lines = rulings(segments);
  const angle = [], distance = [], distribution = [], footpoints = [], striction = [];
  for (let i = 0; i + 1 < lines.length; i++) {
    const [r0, r1] = [lines[i], lines[i + 1]];
    const d = sub(r1.point, r0.point);
    const c = cross(r0.dir, r1.dir);
    const s = norm(c);
    const phi = Math.atan2(s, dot(r0.dir, r1.dir));
    const h = dot(d, c) / s;
    const t = dot(cross(d, r1.dir), c) / (s * s);
    const u = dot(cross(d, r0.dir), c) / (s * s);
    angle.push(phi);
    distance.push(h);
    distribution.push(h / phi);
    footpoints.push(add(r0.point, scale(r0.dir, t)), add(r1.point, scale(r1.dir, u)));
  }
  for (let i = 1; i + 1 < lines.length; i++) striction.push(scale(add(footpoints[2 * i - 1], footpoints[2 * i]), 0.5));
  return { angle, distance, distribution, footpoints, striction };
}

/** One four-point step (8) on both boundary polygons of an open strip, linear ghost ends. */
export function fourPoint(segments, w = 1 / 16) {
  const n = segments.length / 6;
  const pts = (k) => Array.from({ length: n }, (_, i) => [segments[6 * i + k], segments[6 * i + k + 1], segments[6 * i + k + 2]]);
  const refine = (p) => {
    const at = (i) => (i < 0 ? sub(scale(p[0], 2), p[1]) : i >= n ? sub(scale(p[n - 1], 2), p[n - 2]) : p[i]);
    const out = [];
    for (let i = 0; i < n - 1; i++) {
      out.push(p[i]);
      out.push(sub(scale(add(at(i), at(i + 1)), 0.5 + w), scale(add(at(i - 1), at(i + 2)), w)));
    }
    out.push(p[n - 1]);
    return out;
  };
  const [a, b] = [refine(pts(0)), refine(pts(3))];
  const result = new Float64Array(6 * a.length);
  a.forEach((p, i) => result.set([...p, ...b[i]], 6 * i));
  return result;
}
