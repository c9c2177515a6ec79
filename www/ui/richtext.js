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

/** The label read aloud: "R_{i,i+1}" → "R i,i+1". */
export function plainRich(/** @type {string} */ text) {
  return parseRich(text)
    .map((p) => (p.kind === 'text' ? p.text : ` ${p.text}`))
    .join('')
    .replace(/\s+/g, ' ')
    .trim();
}
