// Labels with subscripts and superscripts, written as plain text: "R_{i,i+1}", "m_i", "x^2".
// They become DOM text and <sub>/<sup> elements (never markup parsed from a string), SVG
// <tspan>s, or TikZ math — one notation for the view, the legend and the exports.

/**
 * The parts of a label: text runs, subscripts and superscripts.
 * @param {string} text
 * @returns {Array<{text: string, kind: 'text' | 'sub' | 'sup'}>}
 */
export function parseRich(text) {
  const parts = [];
  const re = /([_^])(?:\{([^}]*)\}|(.))/gu;
  let last = 0;
  for (const m of String(text).matchAll(re)) {
    if (m.index > last) parts.push({ text: text.slice(last, m.index), kind: /** @type {const} */ ('text') });
    parts.push({
      text: m[2] ?? m[3],
      kind: m[1] === '_' ? /** @type {const} */ ('sub') : /** @type {const} */ ('sup'),
    });
    last = m.index + m[0].length;
  }
  if (last < text.length) parts.push({ text: text.slice(last), kind: /** @type {const} */ ('text') });
  return parts;
}

/**
 * Appends `text` to `parent` as text nodes and <sub>/<sup> elements.
 * @param {Element} parent
 * @param {string} text
 */
export function appendRich(parent, text) {
  const doc = parent.ownerDocument;
  for (const part of parseRich(text)) {
    if (part.kind === 'text') parent.append(doc.createTextNode(part.text));
    else parent.append(Object.assign(doc.createElement(part.kind), { textContent: part.text }));
  }
  return parent;
}

/** Unicode's subscript and superscript forms of the characters that have one. */
const SCRIPTS = {
  sub: Object.fromEntries(
    [...'0123456789+−-=()aehijklmnoprstuvxβγρφχ'].map((c, k) => [c, [...'₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓᵦᵧᵨᵩᵪ'][k]]),
  ),
  sup: Object.fromEntries(
    [...'0123456789+−-=()abcdefghijklmnoprstuvwxyz'].map((c, k) => [
      c,
      [...'⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻ'][k],
    ]),
  ),
};

/**
 * A script in Unicode's sub- or superscript characters: "i,i+1" → "ᵢ,ᵢ₊₁" (a comma or a space
 * stays as it is); null when a character has no such form.
 */
function scripted(/** @type {string} */ text, /** @type {'sub' | 'sup'} */ kind) {
  const forms = /** @type {Record<string, string>} */ (SCRIPTS[kind]);
  const chars = [...text];
  if (!chars.every((c) => c in forms || c === ',' || c === ' ')) return null;
  return chars.map((c) => forms[c] ?? c).join('');
}

/**
 * Only the subscripts of `text` in Unicode's characters ("m_i" → "mᵢ"), carets left as typed: the
 * texts of an exercise, whose hints may quote a formula ("type u^2").
 */
export function plainSubscripts(/** @type {string} */ text) {
  return String(text).replace(
    /_(?:\{([^}]*)\}|(.))/gu,
    (whole, braced, one) => scripted(braced ?? one, 'sub') ?? whole,
  );
}

/**
 * A label as plain text, for every place that holds no markup (a menu's option, a live region, a
 * tip's words, the readouts a notebook reads): its scripts in Unicode's sub- and superscript
 * characters, "R_{i,i+1}" → "Rᵢ,ᵢ₊₁", "f_{6,5}" → "f₆,₅", "x^2" → "x²" — the one rendering of
 * scripts beside the <sub>/<sup> of appendRich. A script with a character Unicode has no such
 * form of stays readable as "_(…)" or "^(…)".
 */
export function plainRich(/** @type {string} */ text) {
  return parseRich(text)
    .map((p) => {
      if (p.kind === 'text') return p.text;
      const mark = p.kind === 'sub' ? '_' : '^';
      return scripted(p.text, p.kind) ?? (p.text.length === 1 ? `${mark}${p.text}` : `${mark}(${p.text})`);
    })
    .join('')
    .replace(/\s+/g, ' ')
    .trim();
}
