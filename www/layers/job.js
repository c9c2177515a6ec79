// The job a machinist posts from the milling scene: the program's units and the scale of the
// poses, the tool (its end, radius, length, gauge length, holder), feed, spindle speed and
// direction, coolant, the chordal and angular tolerances, the stock box, the clearance and the
// pole cone — page controls kept in the link, handed to the core's G-code post as they are (the
// program's header says them back). The example is drawn in the paper's units, 10 mm each; an
// import opens at 1 unit per unit of its file (millimetres unless the file or the import says
// inches).

/** The program's units. */
export const UNITS = /** @type {const} */ (['mm', 'inch']);

/** The unit of a length of the job: the program's. */
const length = (/** @type {import('../scene.js').Params} */ p) => `milling.unit.${p.units === 'inch' ? 'inch' : 'mm'}`;
/** The unit of a feed: the program's per minute. */
const feed = (/** @type {import('../scene.js').Params} */ p) => `${length(p)}PerMin`;

/**
 * The job's controls, added to the milling scene's parameters (lengths in the program's units,
 * to 4 decimals: an inch field keeps a ten-thousandth).
 * @type {import('../scene.js').Param[]}
 */
export const JOB_PARAMS = [
  {
    key: 'units',
    label: 'milling.param.units',
    type: 'select',
    value: 'mm',
    refit: false,
    options: () => UNITS.map((u) => [u, `milling.units.${u}`]),
    // the job's lengths and feeds go with the units (the same job in the other units)
    sets: (value, p) => inUnits(String(value), p),
  },
  { key: 'scale', label: 'milling.param.scale', type: 'range', min: 0.01, max: 1000, step: 0.01, value: 10 },
  {
    key: 'end',
    label: 'milling.param.end',
    type: 'select',
    value: 'ball',
    refit: false,
    options: () => [
      ['ball', 'milling.end.ball'],
      ['flat', 'milling.end.flat'],
    ],
  },
  {
    key: 'radius',
    label: 'milling.param.radius',
    type: 'range',
    min: 0.01,
    max: 50,
    step: 0.0001,
    value: 2.5,
    unit: length,
  },
  {
    key: 'length',
    label: 'milling.param.length',
    type: 'range',
    min: 0.1,
    max: 300,
    step: 0.0001,
    value: 15,
    unit: length,
  },
  {
    key: 'gauge',
    label: 'milling.param.gauge',
    type: 'range',
    min: 0.1,
    max: 500,
    step: 0.0001,
    value: 60,
    unit: length,
  },
  {
    key: 'holder',
    label: 'milling.param.holder',
    type: 'range',
    min: 0,
    max: 100,
    step: 0.0001,
    value: 16,
    unit: length,
  },
  {
    key: 'holderLength',
    label: 'milling.param.holderLength',
    type: 'range',
    min: 0,
    max: 200,
    step: 0.0001,
    value: 30,
    unit: length,
  },
  { key: 'feed', label: 'milling.param.feed', type: 'range', min: 1, max: 60000, step: 1, value: 1200, unit: feed },
  { key: 'spindle', label: 'milling.param.spindle', type: 'range', min: 10, max: 60000, step: 10, value: 10000 },
  {
    key: 'direction',
    label: 'milling.param.direction',
    type: 'select',
    value: 'cw',
    refit: false,
    options: () => [
      ['cw', 'milling.direction.cw'],
      ['ccw', 'milling.direction.ccw'],
    ],
  },
  {
    key: 'coolant',
    label: 'milling.param.coolant',
    type: 'select',
    value: 'flood',
    refit: false,
    options: () => [
      ['flood', 'milling.coolant.flood'],
      ['mist', 'milling.coolant.mist'],
      ['off', 'milling.coolant.off'],
    ],
  },
  {
    key: 'tolerance',
    label: 'milling.param.tolerance',
    type: 'range',
    min: 0.0001,
    max: 1,
    step: 0.0001,
    value: 0.01,
    unit: length,
  },
  { key: 'angular', label: 'milling.param.angular', type: 'range', min: 0, max: 10, step: 0.01, value: 0 },
  { key: 'stock', label: 'milling.param.stock', type: 'text', value: '', maxLength: 200 },
  {
    key: 'clearance',
    label: 'milling.param.clearance',
    type: 'range',
    min: 0.1,
    max: 100,
    step: 0.0001,
    value: 5,
    unit: length,
  },
  { key: 'cone', label: 'milling.param.cone', type: 'range', min: 0, max: 10, step: 0.1, value: 1 },
];

/** Millimetres per inch. */
const MM_PER_INCH = 25.4;

/**
 * The job of `p` in the units `to`: its lengths and feeds converted from the units of `p` (a
 * 2.5 mm radius becomes 0.0984251968503937 inch, and 2.5 mm again on the way back), and the scale
 * of the poses with them, never clamped to a control's range (a 2.5 inch radius is 63.5 mm, beyond
 * the slider's 50: the slider stands at its end, the field and the program say 63.5; a link read
 * later clamps it and says so), so that the part keeps its size. To 15
 * significant digits in inches and 12 in millimetres: a value typed in either comes back as typed
 * after a way there and back (30 mm is 1.18110236220472 inch, which is 29.9999999999999 mm to 15
 * digits). The stock box too, where it reads as six numbers (written back space-separated); a
 * text that does not stays as typed. Nothing for the same units.
 * @param {string} to
 * @param {import('../scene.js').Params} p
 * @returns {import('../scene.js').Params}
 */
export function inUnits(to, p) {
  const from = p.units === 'inch' ? 'inch' : 'mm';
  if (to === from || !UNITS.includes(/** @type {any} */ (to))) return {};
  const [factor, digits] = to === 'inch' ? [1 / MM_PER_INCH, 15] : [MM_PER_INCH, 12];
  /** @type {import('../scene.js').Params} */
  const out = {};
  const convert = (/** @type {number} */ x) => Number((x * factor).toPrecision(digits));
  for (const q of JOB_PARAMS) {
    const value = Number(p[q.key]);
    if (!(q.unit === length || q.unit === feed || q.key === 'scale') || !Number.isFinite(value)) continue;
    out[q.key] = convert(value);
  }
  // the stock box, where it reads as one (its six numbers, space-separated)
  const stock = stockOf(String(p.stock ?? ''));
  if (stock) out.stock = stock.flat().map(convert).join(' ');
  return out;
}

/**
 * The stock box a text gives: six numbers "xmin ymin zmin xmax ymax zmax" (spaces, commas or
 * semicolons between them; a decimal comma where semicolons separate), or null for the default
 * (the tips' box grown by 1 mm); undefined when the text is not six numbers.
 * @param {string} text
 * @returns {[[number, number, number], [number, number, number]] | null | undefined}
 */
export function stockOf(text) {
  const t = String(text ?? '').trim();
  if (!t) return null;
  const fields = t.includes(';') ? t.split(/[;\s]+/).map((f) => f.replace(',', '.')) : t.split(/[,\s]+/);
  const x = fields.filter(Boolean).map(Number);
  if (x.length !== 6 || !x.every(Number.isFinite)) return undefined;
  return [
    [x[0], x[1], x[2]],
    [x[3], x[4], x[5]],
  ];
}

/**
 * The tool of the job in the poses' units (what the view draws): its radius and length divided
 * by the scale.
 * @param {Record<string, unknown>} p
 * @returns {{ radius: number, length: number, end: 'ball' | 'flat' }}
 */
export function drawnTool(p) {
  const s = Number(p.scale);
  return { radius: Number(p.radius) / s, length: Number(p.length) / s, end: p.end === 'flat' ? 'flat' : 'ball' };
}

/**
 * The options of the core's post for the job of parameters `p` (the machine, dialect and mode
 * besides): what the controls say, as they say it.
 * @param {Record<string, unknown>} p
 * @param {{ stride: number, lines?: number[] }} [input]  how the poses were numbered as given
 * @returns {import('../../pkg/cam/ruledlab_cam.js').GcodeOptions}
 */
export function jobOptions(p, input) {
  const holder = Number(p.holder) > 0 && Number(p.holderLength) > 0;
  const stock = stockOf(String(p.stock));
  return {
    units: /** @type {'mm' | 'inch'} */ (p.units === 'inch' ? 'inch' : 'mm'),
    scale: Number(p.scale),
    feed: Number(p.feed),
    spindle: Number(p.spindle),
    direction: /** @type {'cw' | 'ccw'} */ (p.direction === 'ccw' ? 'ccw' : 'cw'),
    coolant: /** @type {'flood' | 'mist' | 'off'} */ (p.coolant),
    tolerance: Number(p.tolerance),
    ...(Number(p.angular) > 0 ? { angularTolerance: Number(p.angular) } : {}),
    gauge: Number(p.gauge),
    ...(holder ? { holder: { radius: Number(p.holder), length: Number(p.holderLength) } } : {}),
    ...(stock ? { stock } : {}),
    clearance: Number(p.clearance),
    poleCone: Number(p.cone),
    ...(input ? { input } : {}),
  };
}

/**
 * The parameters an import of tool poses opens the milling scene with: 1 unit per unit of the
 * file, in its units (millimetres unless it says inches; in inches the tolerance 0.0004 and the
 * clearance 0.2), and the tool its file names.
 * @param {import('../scene.js').ImportedData} data
 * @returns {import('../scene.js').Params}
 */
export function importParams(data) {
  const inch = data.units === 'inch';
  // in inches the tolerance and clearance a machinist writes (the core's inch defaults)
  /** @type {import('../scene.js').Params} */
  const params = inch ? { scale: 1, units: 'inch', tolerance: 0.0004, clearance: 0.2 } : { scale: 1, units: 'mm' };
  if (data.tool)
    Object.assign(params, {
      end: data.tool.end,
      radius: data.tool.radius,
      length: data.tool.length,
      gauge: Math.max(60, 4 * data.tool.length),
    });
  return params;
}
