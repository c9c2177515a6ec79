// The view as a TikZ picture for LaTeX, drawn like svg.js: light flat facets (hatched in black
// and white where two surfaces must be told apart), hidden pieces of lines thin and dashed (or
// left out), visible lines and dots over everything, exact curves on a white halo; labels as
// math, the legend under the picture, one entry below the other. Pure ASCII: symbols as math
// ($R_{i}$, $d_{1}$, $\varphi$), other letters as TeX accents (\"u), so it compiles with pdflatex,
// lualatex and xelatex with nothing but \usepackage{tikz}. Deterministic for a given view, so a
// known scene's export can be checked exactly.
import {
  figureOf,
  paint,
  hiddenLook,
  facetColour,
  hatchLines,
  HATCH,
  printFrame,
  dashFor,
  runLength,
} from './projection.js';
import { HATCH_SPACING, PRINT_WIDTH } from '../limits.js';
import { parseRich } from '../ui/richtext.js';
import { append } from '../reduce.js';

/** Letters and signs that are symbols: written in math mode. */
const MATH = {
  α: '\\alpha',
  β: '\\beta',
  γ: '\\gamma',
  δ: '\\delta',
  ε: '\\varepsilon',
  ζ: '\\zeta',
  η: '\\eta',
  θ: '\\theta',
  κ: '\\kappa',
  λ: '\\lambda',
  μ: '\\mu',
  ν: '\\nu',
  ξ: '\\xi',
  π: '\\pi',
  ρ: '\\rho',
  σ: '\\sigma',
  τ: '\\tau',
  φ: '\\varphi',
  χ: '\\chi',
  ψ: '\\psi',
  ω: '\\omega',
  Γ: '\\Gamma',
  Δ: '\\Delta',
  Θ: '\\Theta',
  Λ: '\\Lambda',
  Π: '\\Pi',
  Σ: '\\Sigma',
  Φ: '\\Phi',
  Ψ: '\\Psi',
  Ω: '\\Omega',
  '−': '-',
  '×': '\\times ',
  '·': '\\cdot ',
  '∈': '\\in ',
  '→': '\\to ',
  '↦': '\\mapsto ',
  '≤': '\\le ',
  '≥': '\\ge ',
  '≈': '\\approx ',
  '≠': '\\ne ',
  '±': '\\pm ',
  '∞': '\\infty ',
  '′': "'",
  '″': "''",
  '°': '^\\circ ',
  '²': '^2',
  '³': '^3',
  '½': '\\tfrac12 ',
  '∂': '\\partial ',
  '√': '\\surd ',
};

/** Letters and punctuation of running text, as ASCII TeX. */
const TEXT = {
  ä: '\\"a',
  ö: '\\"o',
  ü: '\\"u',
  Ä: '\\"A',
  Ö: '\\"O',
  Ü: '\\"U',
  ß: '\\ss{}',
  é: "\\'e",
  è: '\\`e',
  ê: '\\^e',
  á: "\\'a",
  à: '\\`a',
  ó: "\\'o",
  í: "\\'i",
  ç: '\\c{c}',
  ñ: '\\~n',
  '–': '--',
  '—': '---',
  '‘': '`',
  '’': "'",
  '‚': ',',
  '“': '``',
  '”': "''",
  '„': ',,',
  '«': '<<',
  '»': '>>',
  '…': '\\ldots{}',
  '\u00a0': '~',
  '\u202f': '\\,',
  '\u2009': '\\,',
  '&': '\\&',
  '%': '\\%',
  '#': '\\#',
  $: '\\$',
  _: '\\_',
  '{': '\\{',
  '}': '\\}',
  '~': '\\textasciitilde{}',
  '^': '\\textasciicircum{}',
  '\\': '\\textbackslash{}',
  '<': '\\textless{}',
  '>': '\\textgreater{}',
  '|': '\\textbar{}',
};

const SUBSCRIPT_DIGITS = '₀₁₂₃₄₅₆₇₈₉';

/** A character in math mode (ASCII). */
function mathChar(/** @type {string} */ c) {
  if (c in MATH) return MATH[/** @type {keyof typeof MATH} */ (c)];
  if (c === '{' || c === '}') return `\\${c}`;
  if (/^[\x20-\x7e]$/.test(c)) return c;
  return '?';
}

/** Math text: "i,i−1" → "i,i-1", "δ̄" → "\bar{\delta}". */
function mathText(/** @type {string} */ s) {
  return [...s.normalize('NFC').replace(/(.)\u0304/gu, (_, c) => `\u0000${c}`)]
    .map((c, k, all) => (c === '\u0000' ? '' : all[k - 1] === '\u0000' ? `\\bar{${mathChar(c)}}` : mathChar(c)))
    .join('');
}

/**
 * Text with symbols as LaTeX, pure ASCII: words as text (accents as TeX accents, TeX's special
 * characters escaped), symbols — a letter with a subscript or superscript (`R_{i,i+1}`, `d₁`),
 * Greek letters, signs, a letter with its argument (`s(u)`) — in math mode.
 * "common perpendiculars N_{i,i+1}" → "common perpendiculars $N_{i,i+1}$".
 * @param {string} text
 * @param {{math?: boolean}} [options]   math: all of it is a symbol (a label in the picture)
 */
export function texText(text, { math = false } = {}) {
  // Unicode subscript digits as subscripts: "d₁" → "d_{1}"
  const plain = text
    .normalize('NFC')
    .replace(
      new RegExp(`([${SUBSCRIPT_DIGITS}]+)`, 'gu'),
      (d) => `_{${[...d].map((c) => SUBSCRIPT_DIGITS.indexOf(c)).join('')}}`,
    );
  if (math) {
    return `$${parseRich(plain)
      .map((p) => (p.kind === 'text' ? mathText(p.text) : `${p.kind === 'sub' ? '_' : '^'}{${mathText(p.text)}}`))
      .join('')}$`;
  }
  /** @type {Array<{math: boolean, text: string}>} */
  const out = [];
  const push = (/** @type {boolean} */ m, /** @type {string} */ t) => {
    const last = out[out.length - 1];
    if (last && last.math === m) last.text += t;
    else out.push({ math: m, text: t });
  };
  for (const part of parseRich(plain)) {
    if (part.kind !== 'text') {
      // the symbol the script belongs to: the letter (with its bar) just before it
      const last = out[out.length - 1];
      if (last && !last.math) {
        const symbol = /([A-Za-z]\u0304?)$/u.exec(last.text);
        if (symbol) {
          last.text = last.text.slice(0, -symbol[1].length);
          if (!last.text) out.pop();
          push(true, mathText(symbol[1]));
        }
      }
      push(true, `${part.kind === 'sub' ? '_' : '^'}{${mathText(part.text)}}`);
      continue;
    }
    // a single letter with its argument, "s(u)", or with a bar, "R̄", is a symbol
    const pieces = part.text.split(/((?<![A-Za-z])[A-Za-z]\([a-z, ]+\)|[A-Za-z]\u0304)/u);
    pieces.forEach((piece, k) => {
      if (k % 2) {
        push(true, mathText(piece));
        return;
      }
      for (const c of piece) {
        if (c in MATH) push(true, MATH[/** @type {keyof typeof MATH} */ (c)]);
        else if (c in TEXT) push(false, TEXT[/** @type {keyof typeof TEXT} */ (c)]);
        else if (/^[\x20-\x7e]$/.test(c)) push(false, c);
        else push(false, '?');
      }
    });
  }
  // a symbol's argument right after it: "$e_{3}$(u)" → "$e_{3}(u)$"
  for (let k = 0; k + 1 < out.length; k++) {
    const arg = /^\([a-z, ]+\)/.exec(out[k + 1].text);
    if (out[k].math && !out[k + 1].math && arg) {
      out[k].text += arg[0];
      out[k + 1].text = out[k + 1].text.slice(arg[0].length);
    }
  }
  return out
    .filter((s) => s.text)
    .map((s) => (s.math ? `$${s.text.trim()}$` : s.text))
    .join('');
}

/** A label as TeX math: "R_{i,i+1}" → "$R_{i,i+1}$", "δ̄_i" → "$\bar{\delta}_{i}$". */
export function texLabel(/** @type {string} */ text) {
  return texText(text, { math: true });
}

/**
 * The TikZ picture of a stage's current view, cropped to its drawing and `width` cm wide (8 by
 * default: a column); line widths, dashes and dots in points, the same on paper at any width.
 * @param {import('../stage.js').Stage} stage
 * @param {import('./svg.js').FigureOptions} [options]
 */
export function exportTikz(
  stage,
  { bw = false, legend = true, labels = true, hidden = 'dashed', width = PRINT_WIDTH.default } = {},
) {
  const fig = figureOf(stage);
  const frame = printFrame(fig, { width, bw, labels, hidden });
  // cm per pixel of the figure; the origin at the lower left corner of the drawing's box
  const s = frame.mm / 10;
  const bottom = frame.y + frame.h;
  const n = (/** @type {number} */ x) =>
    (Math.round(x * 1000) / 1000)
      .toFixed(3)
      .replace(/\.?0+$/, '')
      .replace(/^-0$/, '0');
  const at = (/** @type {number} */ x, /** @type {number} */ y) => `(${n((x - frame.x) * s)},${n((bottom - y) * s)})`;
  const path = (/** @type {number[]} */ p) => {
    const out = [];
    for (let k = 0; k + 1 < p.length; k += 2) out.push(at(p[k], p[k + 1]));
    return out.join(' -- ');
  };
  const pt = (/** @type {number} */ px) => `${n(px * 0.75)}pt`;
  const dash = (/** @type {number[] | null} */ d) =>
    d ? `, dash pattern=${d.map((x, k) => `${k % 2 ? 'off' : 'on'} ${pt(x)}`).join(' ')}` : '';
  /**
   * The runs of a dashed line by the pattern each is drawn with (a short one gets a shorter
   * pattern, projection.js's dashFor), the style's first; a solid line's all in one.
   * @param {Array<{points: number[]}>} runs @param {number[] | null} pattern
   * @returns {Array<[number[] | null, string]>}
   */
  const byDash = (runs, pattern) => {
    if (!pattern) return [[null, runs.map((r) => path(r.points)).join(' ')]];
    /** @type {Map<string, {dash: number[], paths: string[]}>} */
    const groups = new Map([[String(pattern), { dash: pattern, paths: [] }]]);
    for (const r of runs) {
      const own = dashFor(pattern, runLength(r.points) / frame.nat).map((x) => Math.round(x * 100) / 100);
      const key = String(own[0] === pattern[0] ? pattern : own);
      if (!groups.has(key)) groups.set(key, { dash: own, paths: [] });
      /** @type {{paths: string[]}} */ (groups.get(key)).paths.push(path(r.points));
    }
    return [...groups.values()].filter((g) => g.paths.length).map((g) => [g.dash, g.paths.join(' ')]);
  };
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
    return /** @type {string} */ (colours.get(key));
  };
  /** @type {string[]} */
  const body = [];

  // surfaces: thousands of facets, so in PGF's quick path commands (three times faster to
  // typeset than TikZ paths), consecutive facets of one colour in one path
  // (\rlM, \rlL: moveto and lineto in points, defined inside the picture)
  const q = (/** @type {number} */ x, /** @type {number} */ y) =>
    `{${((x - frame.x) * s * 28.45274).toFixed(1)}}{${((bottom - y) * s * 28.45274).toFixed(1)}}`;
  const polygon = (/** @type {number[]} */ p) => {
    let out = '';
    for (let k = 0; k + 1 < p.length; k += 2) out += `\\rl${k ? 'L' : 'M'}${q(p[k], p[k + 1])}`;
    return `${out}\\pgfpathclose`;
  };
  /** @type {{head: string, paths: string[]}} */
  let group = { head: '', paths: [] };
  const flush = () => {
    if (group.paths.length)
      append(body, [`\\begin{pgfscope}${group.head}`, ...group.paths, '\\pgfusepathqfill\\end{pgfscope}']);
    group = { head: '', paths: [] };
  };
  for (const facet of fig.facets) {
    const look = /** @type {import('./projection.js').AreaLook} */ (paint(facet.style, bw));
    const fill = colour(facetColour(look, facet, bw));
    const head = `\\pgfsetfillcolor{${fill}}${look.opacity < 1 ? `\\pgfsetfillopacity{${n(look.opacity)}}` : ''}`;
    if (group.head !== head) {
      flush();
      group.head = head;
    }
    group.paths.push(polygon(facet.points));
    if (look.hatch) {
      flush();
      const lines = hatchLines(facet.points, look.hatch, HATCH_SPACING * frame.nat);
      if (lines.length)
        body.push(
          `\\begin{pgfscope}\\pgfsetstrokecolor{${colour([HATCH.grey, HATCH.grey, HATCH.grey])}}\\pgfsetlinewidth{${pt(HATCH.width)}}`,
          lines.map((l) => `\\rlM${q(l[0], l[1])}\\rlL${q(l[2], l[3])}`).join(''),
          '\\pgfusepathqstroke\\end{pgfscope}',
        );
    }
  }
  flush();

  // hidden pieces, thin and dashed
  if (hidden !== 'omit')
    for (const set of fig.lines) {
      const runs = set.runs.filter((r) => !r.visible);
      if (!runs.length) continue;
      const style = /** @type {any} */ (paint(set.style, bw));
      // (a hidden dot is left out: a point behind a surface says nothing its lines do not)
      if (set.kind === 'points') continue;
      const look = hiddenLook(style, bw);
      const opacity = look.opacity < 1 ? `, draw opacity=${n(look.opacity)}` : '';
      for (const [pattern, paths] of byDash(runs, look.dash))
        body.push(`\\draw[${colour(look.color)}, line width=${pt(look.width)}${dash(pattern)}${opacity}] ${paths};`);
    }

  // what is seen, in the scene's order
  for (const set of fig.lines) {
    const runs = set.runs.filter((r) => r.visible);
    if (!runs.length) continue;
    if (set.kind === 'points') {
      const look = /** @type {import('./projection.js').PointLook} */ (paint(set.style, bw));
      for (const r of runs) {
        const c = `${at(r.points[0], r.points[1])} circle (${pt(look.radius)})`;
        body.push(
          look.hollow
            ? `\\filldraw[fill=white, draw=${colour(look.color)}, line width=0.6pt] ${c};`
            : `\\fill[${colour(look.color)}] ${c};`,
        );
      }
      continue;
    }
    const look = /** @type {import('./projection.js').LineLook} */ (paint(set.style, bw));
    if (look.halo)
      body.push(`\\draw[white, line width=${pt(look.width + 3)}] ${runs.map((r) => path(r.points)).join(' ')};`);
    const opacity = look.opacity < 1 ? `, draw opacity=${n(look.opacity)}` : '';
    for (const [pattern, paths] of byDash(runs, look.dash))
      body.push(`\\draw[${colour(look.color)}, line width=${pt(look.width)}${dash(pattern)}${opacity}] ${paths};`);
  }

  if (labels)
    for (const l of fig.labels)
      body.push(
        `\\node[anchor=north west, inner sep=1pt, fill=white, fill opacity=0.85, text opacity=1] at ${at(l.x, l.y)} {${texLabel(l.text)}};`,
      );

  // the legend under the picture: each entry's node hangs from the one above, so none overlaps;
  // its text wraps within the figure's width (at least 2 cm)
  if (legend && fig.legend.length) {
    const text = Math.max(2, frame.w * s - 1.3 - 0.106);
    fig.legend.forEach((entry, k) => {
      const name = `rl-legend-${k}`;
      const where = k === 0 ? `(${n(1.3)},${n(-0.2)})` : `(rl-legend-${k - 1}.south west)`;
      body.push(
        `\\node[anchor=north west, inner sep=1.5pt, text width=${n(text)}cm, align=left, font=\\small] (${name}) at ${where} {${texText(entry.label)}};`,
      );
      const look = /** @type {any} */ (paint(entry.style, bw));
      const sample = [];
      if ('width' in look) {
        sample.push(
          `\\draw[${colour(look.color)}, line width=${pt(Math.min(Math.max(look.width, 0.6), 6))}${dash(look.dash)}] (-1.1,0) -- (-0.2,0);`,
        );
      } else if ('radius' in look) {
        sample.push(
          look.hollow
            ? `\\filldraw[fill=white, draw=${colour(look.color)}, line width=0.6pt] (-0.65,0) circle (${pt(Math.min(look.radius, 5))});`
            : `\\fill[${colour(look.color)}] (-0.65,0) circle (${pt(Math.min(look.radius, 5))});`,
        );
      } else {
        sample.push(
          `\\filldraw[fill=${colour(look.color)}, draw=${colour([0.6, 0.6, 0.6])}, line width=0.3pt] (-1,-0.13) rectangle (-0.3,0.13);`,
        );
        if (look.hatch) {
          // the hatching of a 0.7 × 0.26 cm box, drawn in its own pixels (1 cm = 1/s px)
          const [w, h] = [0.7 / s, 0.26 / s];
          const spacing = HATCH_SPACING * frame.nat;
          const lines = [
            ...hatchLines([0, 0, w, 0, w, h], look.hatch, spacing),
            ...hatchLines([0, 0, w, h, 0, h], look.hatch, spacing),
          ];
          const local = (/** @type {number} */ x, /** @type {number} */ y) => `(${n(-1 + x * s)},${n(0.13 - y * s)})`;
          if (lines.length)
            sample.push(
              `\\draw[${colour([HATCH.grey, HATCH.grey, HATCH.grey])}, line width=${pt(HATCH.width)}] ${lines.map((l) => `${local(l[0], l[1])} -- ${local(l[2], l[3])}`).join(' ')};`,
            );
        }
      }
      // (the sample beside the entry's first line)
      append(body, [`\\begin{scope}[shift={([yshift=-5.2pt]${name}.north west)}]`, ...sample, '\\end{scope}']);
    });
  }
  const defs = [...colours].map(([hexColour, name]) => `\\definecolor{${name}}{HTML}{${hexColour}}`);
  return [
    `% ${texComment(fig.title)}: exported by ruledlab (TikZ; needs \\usepackage{tikz}; pdflatex, lualatex or xelatex)`,
    '\\begin{tikzpicture}[line cap=round, line join=round]',
    ...(fig.facets.length
      ? ['\\def\\rlM#1#2{\\pgfpathqmoveto{#1pt}{#2pt}}\\def\\rlL#1#2{\\pgfpathqlineto{#1pt}{#2pt}}']
      : []),
    ...defs,
    // the drawing's box, margin included: the picture is as wide as asked (PGF's quick paths of
    // the surfaces do not count in TikZ's own bounding box)
    `\\path (0,0) rectangle ${at(frame.x + frame.w, frame.y)};`,
    ...body,
    '\\end{tikzpicture}',
    '',
  ].join('\n');
}

/** A title for a TeX comment: ASCII, subscripts inline. */
function texComment(/** @type {string} */ title) {
  return [...title.replace(/[_^]\{?([^}\s]*)\}?/g, '$1')]
    .map((c) =>
      /^[\x20-\x7e]$/.test(c)
        ? c
        : ({ ä: 'ae', ö: 'oe', ü: 'ue', Ä: 'Ae', Ö: 'Oe', Ü: 'Ue', ß: 'ss', '–': '-', '—': '-', '−': '-', '’': "'" }[
            c
          ] ?? ''),
    )
    .join('')
    .replace(/%/g, 'percent');
}
