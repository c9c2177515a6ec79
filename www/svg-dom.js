// SVG built with the DOM, never from strings (so no text can become markup): the element maker
// the figures, the plot and the exports share, and the frame of a small standalone figure.

export const SVG = 'http://www.w3.org/2000/svg';
const XML = 'http://www.w3.org/XML/1998/namespace';

/**
 * A function making SVG elements of `doc`: `make(tag, attributes, text)`.
 * @param {Document} doc
 */
export function svgMaker(doc) {
  return (
    /** @type {string} */ tag,
    /** @type {Record<string, string | number>} */ attrs = {},
    /** @type {string} */ text = '',
  ) => {
    const e = doc.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs))
      if (k.startsWith('xml:')) e.setAttributeNS(XML, k, String(v));
      else e.setAttribute(k, String(v));
    if (text) e.textContent = text;
    return e;
  };
}

/**
 * A standalone figure of `width` × `height` user units on the page's paper colour, its title
 * its accessible name (the log-log plot, the butterfly stencil).
 * @param {ReturnType<typeof svgMaker>} make
 * @param {{ width: number, height: number, title: string }} options
 * @returns {SVGSVGElement}
 */
export function svgFigure(make, { width, height, title }) {
  const svg = /** @type {SVGSVGElement} */ (
    make('svg', {
      xmlns: SVG,
      version: '1.1',
      viewBox: `0 0 ${width} ${height}`,
      width,
      height,
      'font-family': 'Helvetica, Arial, sans-serif',
      'font-size': 13.5,
      role: 'img',
    })
  );
  svg.setAttribute('aria-label', title);
  svg.append(make('title', {}, title), make('rect', { x: 0, y: 0, width, height, fill: '#fbfaf7' }));
  return svg;
}
