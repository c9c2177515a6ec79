// Hands on the page for the tests: a finger (touch events through Chrome DevTools, off by up to
// ±4 CSS px as a finger is), where the handles are on screen as the reader sees their rings, and
// the numbers the page shows read back.

/** @typedef {import('playwright-core').Page} Page */
/** @typedef {import('playwright-core').CDPSession} CDPSession */

/** A finger: reproducible offsets of up to ±4 CSS px (mulberry32). */
export function finger(seed = 47) {
  let a = seed;
  const random = () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return () => 8 * random() - 4;
}

/** Touches on the page with a finger's imprecision. */
export class Hand {
  /** @param {Page} page @param {CDPSession} cdp @param {() => number} off */
  constructor(page, cdp, off) {
    Object.assign(this, { page, cdp, off });
  }
  /** @param {'touchStart' | 'touchMove'} type @param {number} x @param {number} y */
  async touch(type, x, y) {
    await this.cdp.send('Input.dispatchTouchEvent', {
      type,
      touchPoints: [{ x: x + this.off(), y: y + this.off(), radiusX: 6, radiusY: 6 }],
    });
  }
  async lift() {
    await this.cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await drawn(this.page);
  }
  /** A drag from (x0, y0) to (x1, y1) in `steps` moves, after holding still `hold` ms. */
  async drag(
    /** @type {number} */ x0,
    /** @type {number} */ y0,
    /** @type {number} */ x1,
    /** @type {number} */ y1,
    steps = 8,
    hold = 0,
  ) {
    await this.touch('touchStart', x0, y0);
    if (hold) await this.page.waitForTimeout(hold);
    for (let s = 1; s <= steps; s++)
      await this.touch('touchMove', x0 + ((x1 - x0) * s) / steps, y0 + ((y1 - y0) * s) / steps);
    await this.lift();
  }
  /** A tap on an element (its centre, off by a finger's error), scrolled into sight first unless `scroll` is false. */
  async tap(/** @type {import('playwright-core').Locator} */ locator, scroll = true) {
    if (scroll) await locator.scrollIntoViewIfNeeded();
    const box = /** @type {{x: number, y: number, width: number, height: number}} */ (await locator.boundingBox());
    const x = box.x + box.width / 2,
      y = box.y + box.height / 2;
    await this.touch('touchStart', x, y);
    await this.lift();
  }
}

/** Two animation frames: the change and its picture. */
export const drawn = (/** @type {Page} */ page) =>
  page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/** Every handle on the page (CSS px), as the reader sees the rings, and each ruling's ends. */
export const handlesOnPage = (/** @type {Page} */ page) =>
  page.evaluate(() => {
    const { stage } = window.ruledlab;
    const b = stage.viewer.canvas.getBoundingClientRect();
    const bar = /** @type {HTMLElement} */ (document.querySelector('.rl-bar')).getBoundingClientRect();
    const m = stage.viewer.camera.viewProj(b.width / b.height);
    return stage.editor.handles().map((h) => {
      const [x, y, z] = h.world;
      const w = m[3] * x + m[7] * y + m[11] * z + m[15];
      const sx = b.left + (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * b.width;
      const sy = b.top + ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * b.height;
      return {
        index: h.index,
        x: sx,
        y: sy,
        free: w > 0 && sx > b.left + 12 && sx < b.right - 12 && sy > b.top + 12 && sy < bar.top - 8,
      };
    });
  });

/** A number as the page shows it ("0.438", "−1.74", "4.1·10⁻³", "exact"), read back. */
export function readNumber(/** @type {string} */ text) {
  if (/exact/.test(text)) return 0;
  const m = /([−-]?[\d.]+)(?:·10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?/.exec(text);
  if (!m) return Number.NaN;
  const sup = '⁰¹²³⁴⁵⁶⁷⁸⁹';
  const power = m[2] ? [...m[2]].map((c) => (c === '⁻' ? '-' : String(sup.indexOf(c)))).join('') : '0';
  return Number(m[1].replace('−', '-')) * 10 ** Number(power);
}

/** The live value of the exercise's condition beside the dragged point. */
export async function liveValue(/** @type {Page} */ page) {
  const text = await page.locator('.rl-handle-tip .rl-tip-value').last().innerText();
  return readNumber(text.slice(text.indexOf(':') + 1).split('(')[0]);
}

/** The stage's input now, as plain arrays. */
export const inputNow = (/** @type {Page} */ page) =>
  page.evaluate(() => {
    const input = window.ruledlab.stage.currentInput() ?? {};
    return Object.fromEntries(Object.entries(input).map(([k, v]) => [k, Array.from(v)]));
  });
