// The focal figure (beyond the paper): a grid of lines by kind (hyperbolic, elliptic,
// parabolic), its focal sheets where real, the torsal strokes, and the readouts of kinds,
// normality and the linear complex. Drawn by the focal scene, "Your congruence" and "Your data".

/**
 * Segments of the lines whose kind is `kind`.
 * @param {Float32Array} segments   6 per line
 * @param {Uint8Array} kinds
 * @param {number} kind
 */
function linesOfKind(segments, kinds, kind) {
  const out = new Float32Array(6 * kinds.reduce((n, k) => n + (k === kind ? 1 : 0), 0));
  let at = 0;
  kinds.forEach((k, i) => {
    if (k !== kind) return;
    out.set(segments.subarray(6 * i, 6 * i + 6), at);
    at += 6;
  });
  return out;
}

/**
 * The focal figure of a grid of lines: shared with "Your congruence".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').LineCongruence} grid
 * @param {{sheets: boolean, torsal: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @returns {{layers: import('../scene.js').Layer[], readouts: import('../scene.js').Readout[], sentence: string, positions: Float32Array[]}}
 */
export function focalFigure(own, grid, p, { t }) {
  const focal = grid.focal();
  const n = focal.kind.length;
  const count = [0, 1, 2].map((k) => focal.kind.reduce((s, x) => s + (x === k ? 1 : 0), 0));
  const real = Array.from(focal.normality).filter(Number.isFinite);
  const segments = grid.segmentsF32();
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    { kind: 'segments', style: 'focalHyperbolic', positions: linesOfKind(segments, focal.kind, 1) },
    { kind: 'segments', style: 'focalElliptic', positions: linesOfKind(segments, focal.kind, 0) },
    { kind: 'segments', style: 'focalParabolic', positions: linesOfKind(segments, focal.kind, 2) },
  ];
  /** @type {Float32Array[]} */
  const positions = [segments];
  if (p.sheets) {
    for (const sheet of /** @type {const} */ ([1, 2])) {
      const mesh = grid.focalSheetF32(sheet);
      if (mesh.indices.length === 0) continue;
      layers.push({ kind: 'mesh', style: `focal${sheet}`, positions: mesh.positions, indices: mesh.indices, normals: mesh.normals });
      // frame only what is drawn: vertices of kept triangles
      const used = new Float32Array(3 * mesh.indices.length);
      mesh.indices.forEach((v, k) => used.set(mesh.positions.subarray(3 * v, 3 * v + 3), 3 * k));
      positions.push(used);
    }
  }
  if (p.torsal) layers.push({ kind: 'segments', style: 'torsal', positions: grid.torsalStrokesF32() });
  // looser than the default 1e-9: imported data carry the digits a file printed
  const complex = grid.linearComplex({ tolerance: 1e-6 });
  const normality = real.length ? Math.max(...real) : NaN;
  /** @type {import('../scene.js').Readout[]} */
  const readouts = [
    { label: 'focal.readout.hyperbolic', value: `${count[1]} / ${n}` },
    { label: 'focal.readout.elliptic', value: `${count[0]} / ${n}` },
    { label: 'focal.readout.parabolic', value: `${count[2]} / ${n}` },
    { label: 'focal.readout.normality', value: real.length ? normality : t('focal.none'), exactZero: true },
    { label: 'focal.readout.complex', value: t(`complex.kind.${complex.kind}`) },
  ];
  // a pitch at rounding level is 0: the lines all meet the axis (Example 5: the z-axis)
  if (complex.kind === 'complex') readouts.push({ label: 'focal.readout.pitch', value: Math.abs(complex.pitch) < 1e-12 ? 0 : complex.pitch, exactZero: true });
  const sentence = t('focal.describe', {
    hyperbolic: count[1],
    elliptic: count[0],
    parabolic: count[2],
    lines: n,
    normality: real.length ? t('focal.describe.normality', { normality }) : '',
    complex: t(`complex.kind.${complex.kind}`),
  });
  return { layers, readouts, sentence, positions };
}
