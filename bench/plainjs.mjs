// The plain-JavaScript baseline of bench/wasm.mjs, written as carefully as the Rust: typed
// arrays in and out, one pass over the rulings, no per-ruling objects or closures in the hot
// loop, the same formulas, tolerance and end rules as the core (bench/wasm.mjs checks that the
// numbers agree). A reader who writes their own JS should get about these times.

/** The core's PARALLEL_SIN (src/tolerance.rs): below it a pair counts as parallel. */
const PARALLEL_SIN = 1e-9;

/**
 * Output arrays of `invariantsInto` for `n` rulings (open surface), the layout of the wasm API.
 * @param {number} n
 */
export function invariantsArrays(n) {
  const pairs = n - 1,
    interior = n - 2;
  return {
    angle: new Float64Array(pairs),
    distance: new Float64Array(pairs),
    distribution: new Float64Array(pairs),
    footpoints: new Float64Array(6 * pairs),
    centralNormal: new Float64Array(3 * pairs),
    striction: new Float64Array(3 * interior),
    distributionMean: new Float64Array(interior),
    perpendicularMidpoints: new Float64Array(3 * pairs),
    parallel: new Uint8Array(pairs),
  };
}

/**
 * Section 2's invariants of an open surface (6 numbers per ruling) into `out`, in one pass:
 * the unit direction of each ruling is computed once and carried to the next pair.
 * @param {Float64Array} s
 * @param {ReturnType<typeof invariantsArrays>} out
 */
export function invariantsInto(s, out) {
  const n = s.length / 6;
  const {
    angle,
    distance,
    distribution,
    footpoints: f,
    centralNormal: nn,
    striction: m,
    distributionMean: dm,
    perpendicularMidpoints: pm,
    parallel,
  } = out;
  // the previous ruling: point and unit direction
  let px = s[0],
    py = s[1],
    pz = s[2];
  let ex = s[3] - px,
    ey = s[4] - py,
    ez = s[5] - pz;
  let len = Math.sqrt(ex * ex + ey * ey + ez * ez);
  ex /= len;
  ey /= len;
  ez /= len;
  let prevDelta = NaN;
  for (let i = 0; i + 1 < n; i++) {
    const k = 6 * (i + 1);
    const qx = s[k],
      qy = s[k + 1],
      qz = s[k + 2];
    let gx = s[k + 3] - qx,
      gy = s[k + 4] - qy,
      gz = s[k + 5] - qz;
    len = Math.sqrt(gx * gx + gy * gy + gz * gz);
    gx /= len;
    gy /= len;
    gz /= len;
    const dx = qx - px,
      dy = qy - py,
      dz = qz - pz;
    const cx = ey * gz - ez * gy,
      cy = ez * gx - ex * gz,
      cz = ex * gy - ey * gx;
    const sin = Math.sqrt(cx * cx + cy * cy + cz * cz);
    const phi = Math.atan2(sin, ex * gx + ey * gy + ez * gz);
    angle[i] = phi;
    let delta, f0x, f0y, f0z, f1x, f1y, f1z;
    if (sin < PARALLEL_SIN) {
      const along = dx * ex + dy * ey + dz * ez;
      const rx = dx - along * ex,
        ry = dy - along * ey,
        rz = dz - along * ez;
      distance[i] = Math.sqrt(rx * rx + ry * ry + rz * rz);
      delta = NaN;
      f0x = f0y = f0z = f1x = f1y = f1z = NaN;
      nn[3 * i] = nn[3 * i + 1] = nn[3 * i + 2] = NaN;
      parallel[i] = 1;
    } else {
      const h = (dx * cx + dy * cy + dz * cz) / sin;
      distance[i] = h;
      delta = h / phi;
      const sin2 = sin * sin;
      // t = (d × e1)·c / sin², s = (d × e0)·c / sin²
      const t = ((dy * gz - dz * gy) * cx + (dz * gx - dx * gz) * cy + (dx * gy - dy * gx) * cz) / sin2;
      const u = ((dy * ez - dz * ey) * cx + (dz * ex - dx * ez) * cy + (dx * ey - dy * ex) * cz) / sin2;
      f0x = px + t * ex;
      f0y = py + t * ey;
      f0z = pz + t * ez;
      f1x = qx + u * gx;
      f1y = qy + u * gy;
      f1z = qz + u * gz;
      nn[3 * i] = cx / sin;
      nn[3 * i + 1] = cy / sin;
      nn[3 * i + 2] = cz / sin;
      parallel[i] = 0;
    }
    distribution[i] = delta;
    if (i > 0) {
      // m_i = (f_{i,i−1} + f_{i,i+1})/2: f_{i,i−1} is the second foot of the previous pair
      m[3 * (i - 1)] = 0.5 * (f[6 * i - 3] + f0x);
      m[3 * (i - 1) + 1] = 0.5 * (f[6 * i - 2] + f0y);
      m[3 * (i - 1) + 2] = 0.5 * (f[6 * i - 1] + f0z);
      dm[i - 1] = 0.5 * (prevDelta + delta);
    }
    f[6 * i] = f0x;
    f[6 * i + 1] = f0y;
    f[6 * i + 2] = f0z;
    f[6 * i + 3] = f1x;
    f[6 * i + 4] = f1y;
    f[6 * i + 5] = f1z;
    pm[3 * i] = 0.5 * (f0x + f1x);
    pm[3 * i + 1] = 0.5 * (f0y + f1y);
    pm[3 * i + 2] = 0.5 * (f0z + f1z);
    prevDelta = delta;
    px = qx;
    py = qy;
    pz = qz;
    ex = gx;
    ey = gy;
    ez = gz;
  }
  return out;
}

/** As `invariantsInto`, into fresh arrays (what `invariants()` does). @param {Float64Array} s */
export function invariants(s) {
  return invariantsInto(s, invariantsArrays(s.length / 6));
}

/**
 * One four-point step (8), w = 1/16, of an open strip as one polygon of endpoint pairs (6
 * numbers per ruling), with the core's cubic ghost points at the ends, into `out`
 * (6(2N − 1) numbers). One pass; the interior loop has no branches.
 * @param {Float64Array} s
 * @param {Float64Array} [out]
 */
export function fourPoint(s, out = new Float64Array(6 * (2 * (s.length / 6) - 1))) {
  const n = s.length / 6;
  const w = 1 / 16,
    c = 0.5 + w;
  for (let k = 0; k < 6; k++) {
    // ghost points p_{−1} = 4p_0 − 6p_1 + 4p_2 − p_3 and its mirror at the end (n ≥ 4 here)
    const before = 4 * s[k] - 6 * s[6 + k] + 4 * s[12 + k] - s[18 + k];
    const after = 4 * s[6 * (n - 1) + k] - 6 * s[6 * (n - 2) + k] + 4 * s[6 * (n - 3) + k] - s[6 * (n - 4) + k];
    out[k] = s[k];
    out[6 + k] = c * (s[k] + s[6 + k]) - w * (before + s[12 + k]);
    const last = n - 2;
    out[12 * last + 6 + k] = c * (s[6 * last + k] + s[6 * (last + 1) + k]) - w * (s[6 * (last - 1) + k] + after);
    out[12 * (n - 1) + k] = s[6 * (n - 1) + k];
  }
  for (let i = 1; i + 2 < n; i++) {
    const a = 6 * (i - 1),
      o = 12 * i;
    for (let k = 0; k < 6; k++) {
      out[o + k] = s[a + 6 + k];
      out[o + 6 + k] = c * (s[a + 6 + k] + s[a + 12 + k]) - w * (s[a + k] + s[a + 18 + k]);
    }
  }
  out.set(s.subarray(6 * (n - 2), 6 * (n - 1)), 12 * (n - 2));
  return out;
}
