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
