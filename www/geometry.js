// Flat-array helpers for building GPU buffers from the core's typed arrays (no per-line objects).

/** Segments joining consecutive points of a flat xyz polyline (closed: back to the start). */
export function polylineSegments(points, closed = false) {
  const n = points.length / 3;
  const count = closed ? n : Math.max(n - 1, 0);
  const out = new Float32Array(6 * count);
  for (let i = 0; i < count; i++) {
    const j = (i + 1) % n;
    out.set(points.subarray(3 * i, 3 * i + 3), 6 * i);
    out.set(points.subarray(3 * j, 3 * j + 3), 6 * i + 3);
  }
  return dropNonFinite(out, 6);
}

/** Removes records (of `stride` numbers) that contain NaN or ±∞; returns a Float32Array. */
export function dropNonFinite(data, stride) {
  const out = new Float32Array(data.length);
  let k = 0;
  for (let i = 0; i < data.length; i += stride) {
    let ok = true;
    for (let j = 0; j < stride; j++) ok &&= Number.isFinite(data[i + j]);
    if (ok) {
      for (let j = 0; j < stride; j++) out[k++] = data[i + j];
    }
  }
  return out.subarray(0, k);
}

/**
 * Closes a sampled closed surface for the invariants: R_{N−1}, R_0, …, R_{N−1}, R_0, so
 * that every ruling of the original becomes interior and gets a striction point.
 */
export function wrapClosed(segments) {
  const n = segments.length;
  const out = new Float64Array(n + 12);
  out.set(segments.subarray(n - 6), 0);
  out.set(segments, 6);
  out.set(segments.subarray(0, 6), n + 6);
  return out;
}

/** Equally spaced parameters as the core's sampling uses them. */
export function parameters(count, uMin, uMax, closed) {
  const step = (uMax - uMin) / (closed ? count : Math.max(count - 1, 1));
  return Float64Array.from({ length: count }, (_, i) => uMin + i * step);
}

/** Largest distance between corresponding points of two flat xyz arrays (NaN skipped). */
export function maxDistance(p, q) {
  let m = 0;
  for (let i = 0; i + 2 < p.length; i += 3) {
    const d = Math.hypot(p[i] - q[i], p[i + 1] - q[i + 1], p[i + 2] - q[i + 2]);
    if (d > m) m = d;
  }
  return m;
}

/**
 * Points (flat xyz) in the orthonormal frame (x, y, z) at `origin`, shifted by `offset`:
 * the coordinates ((p − o)·x, (p − o)·y, (p − o)·z) + offset, as a Float32Array.
 */
export function toFrame(points, { origin, x, y, z }, offset = [0, 0, 0]) {
  const out = new Float32Array(points.length);
  for (let i = 0; i < points.length; i += 3) {
    const d0 = points[i] - origin[0], d1 = points[i + 1] - origin[1], d2 = points[i + 2] - origin[2];
    out[i] = d0 * x[0] + d1 * x[1] + d2 * x[2] + offset[0];
    out[i + 1] = d0 * y[0] + d1 * y[1] + d2 * y[2] + offset[1];
    out[i + 2] = d0 * z[0] + d1 * z[1] + d2 * z[2] + offset[2];
  }
  return out;
}

/** 2D points (flat xy) lifted to the plane z = `height`, shifted by `offset`. */
export function lift2d(points, height = 0, offset = [0, 0, 0]) {
  const n = points.length / 2;
  const out = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) {
    out[3 * i] = points[2 * i] + offset[0];
    out[3 * i + 1] = points[2 * i + 1] + offset[1];
    out[3 * i + 2] = height + offset[2];
  }
  return out;
}

/** Largest relative change between corresponding edge lengths of two flat xyz polylines. */
export function maxRelativeEdgeChange(p, q, stride = 3, start = 0) {
  let worst = 0;
  for (let i = start; i + stride + 2 < p.length; i += stride) {
    const a = Math.hypot(p[i + stride] - p[i], p[i + stride + 1] - p[i + 1], p[i + stride + 2] - p[i + 2]);
    const b = Math.hypot(q[i + stride] - q[i], q[i + stride + 1] - q[i + 1], q[i + stride + 2] - q[i + 2]);
    if (a > 0) worst = Math.max(worst, Math.abs(a - b) / a);
  }
  return worst;
}

/**
 * A tube of `radius` about a polyline (flat xyz): rings of `sides` vertices carried along by
 * projecting the previous ring's frame (rotation-minimising), as positions and indices.
 */
export function tube(points, radius, sides = 14) {
  const n = points.length / 3;
  const positions = new Float32Array(3 * n * sides);
  const indices = new Uint32Array(6 * (n - 1) * sides);
  const p = (i) => [points[3 * i], points[3 * i + 1], points[3 * i + 2]];
  const sub3 = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const norm = (a) => { const l = Math.hypot(...a) || 1; return a.map((x) => x / l); };
  const crossp = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  let normal = null;
  for (let i = 0; i < n; i++) {
    const t = norm(sub3(p(Math.min(i + 1, n - 1)), p(Math.max(i - 1, 0))));
    if (!normal) normal = norm(Math.abs(t[2]) < 0.9 ? crossp(t, [0, 0, 1]) : crossp(t, [1, 0, 0]));
    const d = normal[0] * t[0] + normal[1] * t[1] + normal[2] * t[2];
    normal = norm([normal[0] - d * t[0], normal[1] - d * t[1], normal[2] - d * t[2]]);
    const binormal = crossp(t, normal);
    for (let k = 0; k < sides; k++) {
      const a = (2 * Math.PI * k) / sides;
      for (let c = 0; c < 3; c++) positions[3 * (i * sides + k) + c] = points[3 * i + c] + radius * (Math.cos(a) * normal[c] + Math.sin(a) * binormal[c]);
    }
  }
  for (let i = 0, m = 0; i + 1 < n; i++) {
    for (let k = 0; k < sides; k++) {
      const a = i * sides + k, b = i * sides + ((k + 1) % sides), c = a + sides, d = b + sides;
      indices.set([a, c, d, a, d, b], m);
      m += 6;
    }
  }
  return { positions, indices };
}
