// The view as a TikZ picture for LaTeX: the figure's primitives (figure.js) back to front in
// centimetres, labels and legend as math, in colour (Okabe–Ito, defined by name) or in black
// and white. Deterministic for a given view, so a known scene's export can be checked exactly.
import { figureOf, paint } from './figure.js';
import { parseRich } from '../ui/richtext.js';

/** Unicode letters and signs of labels, as TeX. */
const TEX = {
  φ: '\\varphi',
  δ: '\\delta',
  ε: '\\varepsilon',
  θ: '\\theta',
  τ: '\\tau',
  '−': '-',
  '′': "'",
  '·': '\\cdot ',
  '×': '\\times ',
  '∈': '\\in ',
  '→': '\\to ',
  '̄': '',
};

/** A label as TeX math: "R_{i,i+1}" → "$R_{i,i+1}$", "δ̄_i" → "$\bar{\delta}_{i}$". */
export function texLabel(/** @type {string} */ text) {
  const tex = (/** @type {string} */ s) =>
    [...s.replace(/(.)\u0304/gu, (_, c) => `\\bar{${TEX[/** @type {keyof typeof TEX} */ (c)] ?? c}}`)]
      .map((c) => TEX[/** @type {keyof typeof TEX} */ (c)] ?? c)
      .join('');
  return `$${parseRich(text)
    .map((p) => (p.kind === 'text' ? tex(p.text) : `${p.kind === 'sub' ? '_' : '^'}{${tex(p.text)}}`))
    .join('')}$`;
}

/**
 * The TikZ picture of a stage's current view, 12 cm wide.
 * @param {import('../stage.js').Stage} stage
 * @param {import('./svg.js').FigureOptions & {width?: number}} [options]
 */
export function exportTikz(stage, { bw = false, legend = true, labels = true, width = 12 } = {}) {
  const fig = figureOf(stage);
  const s = width / fig.width;
  const n = (/** @type {number} */ x) =>
    (Math.round(x * 1000) / 1000)
      .toFixed(3)
      .replace(/\.?0+$/, '')
      .replace(/^-0$/, '0');
  const at = (/** @type {number} */ x, /** @type {number} */ y) => `(${n(x * s)},${n((fig.height - y) * s)})`;
  /** @type {Map<string, string>} */
  const colours = new Map();
  const colour = (/** @type {number[]} */ c) => {
    const key = c
      .map((x) =>
        Math.round(Math.min(1, Math.max(0, x)) * 255)
          .toString(16)
          .padStart(2, '0'),
      )
      .join('')
      .toUpperCase();
    if (!colours.has(key)) colours.set(key, `rl${colours.size}`);
    return colours.get(key);
  };
  const body = [];
  for (const p of fig.primitives) {
    const look = /** @type {any} */ (paint(p.style, bw));
    if (p.kind === 'segment') {
      const opts = [colour(look.color), `line width=${n(look.width * 0.75)}pt`];
      if (look.dash)
        opts.push(
          `dash pattern=${look.dash.map((/** @type {number} */ d, /** @type {number} */ k) => `${k % 2 ? 'off' : 'on'} ${n(d * 0.75)}pt`).join(' ')}`,
        );
      if (look.opacity < 1) opts.push(`draw opacity=${n(look.opacity)}`);
      body.push(`\\draw[${opts.join(', ')}] ${at(p.points[0], p.points[1])} -- ${at(p.points[2], p.points[3])};`);
    } else if (p.kind === 'dot') {
      const r = `${n(look.radius * 0.75)}pt`;
      body.push(
        look.hollow
          ? `\\filldraw[fill=white, draw=${colour(look.color)}, line width=0.4pt] ${at(p.points[0], p.points[1])} circle (${r});`
          : `\\fill[${colour(look.color)}] ${at(p.points[0], p.points[1])} circle (${r});`,
      );
    } else {
      const base = p.back ? look.back : look.color;
      const c = colour(
        base.map(
          (/** @type {number} */ x) =>
            x * /** @type {number[]} */ (p.fill)[0] + (1 - /** @type {number[]} */ (p.fill)[0]) * 0.08,
        ),
      );
      const opts = [c];
      if (look.opacity < 1) opts.push(`fill opacity=${n(look.opacity)}`);
      body.push(
        `\\fill[${opts.join(', ')}] ${at(p.points[0], p.points[1])} -- ${at(p.points[2], p.points[3])} -- ${at(p.points[4], p.points[5])} -- cycle;`,
      );
    }
  }
  if (labels)
    for (const l of fig.labels)
      body.push(
        `\\node[anchor=north west, inner sep=1pt, fill=white, fill opacity=0.85, text opacity=1] at ${at(l.x, l.y)} {${texLabel(l.text)}};`,
      );
  if (legend) {
    fig.legend.forEach((entry, k) => {
      const y = 14 + 18 * k;
      const look = /** @type {any} */ (paint(entry.style, bw));
      if ('width' in look) {
        const dash = look.dash
          ? `, dash pattern=${look.dash.map((/** @type {number} */ d, /** @type {number} */ i) => `${i % 2 ? 'off' : 'on'} ${n(d * 0.75)}pt`).join(' ')}`
          : '';
        body.push(
          `\\draw[${colour(look.color)}, line width=${n(Math.min(Math.max(look.width, 1.2), 5) * 0.75)}pt${dash}] ${at(18, y)} -- ${at(46, y)};`,
        );
      } else if ('radius' in look) {
        body.push(`\\fill[${colour(look.color)}] ${at(32, y)} circle (${n(Math.min(look.radius, 5) * 0.75)}pt);`);
      } else {
        body.push(`\\fill[${colour(look.color)}] ${at(22, y - 6)} rectangle ${at(42, y + 6)};`);
      }
      body.push(
        `\\node[anchor=west, inner sep=1pt, font=\\small] at ${at(52, y)} {${entry.label.replace(/([_^]\{[^}]*\}|[_^].)/g, (m) => `$${m}$`).replace(/[&%#]/g, (c) => `\\${c}`)}};`,
      );
    });
  }
  const defs = [...colours].map(([hexColour, name]) => `\\definecolor{${name}}{HTML}{${hexColour}}`);
  return [
    `% ${fig.title.replace(/[_^]\{?([^}\s]*)\}?/g, '$1')}: exported by ruledlab (TikZ; needs \\usepackage{tikz})`,
    '\\begin{tikzpicture}',
    ...defs,
    ...body,
    '\\end{tikzpicture}',
    '',
  ].join('\n');
}
