// Many rulings given to <ruled-view> as data, as the notebook's View.from_segments sends them (a
// Float64Array, six numbers a ruling): 100 000 and 10⁶ are drawn with no error and counted in the
// readout, at the level of detail the view says (above 20 000 rulings the strip, the rulings and
// the striction curve through every k-th ruling; the numbers of all); how long that took and the
// page's longest pause meanwhile are reported (speed is measured, not judged: the times go to the
// artifacts and the book, never into an assertion). Drawing every ruling's strip, lines, normals,
// points and handles had taken 26 s for 100 000 rulings and more than 5 minutes for 10⁶ in the
// test machine's software WebGL (SwiftShader), nearly all of it native drawing. The reductions
// that failed from about 125 000 rulings are tested in Node (tests/node/spreads.test.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { pageSession, ARTIFACTS } from './browser.mjs';

const session = pageSession();

for (const n of [100_000, 1_000_000]) {
  test(`a <ruled-view> given ${n.toLocaleString('en')} rulings as data draws them without an error`, {
    timeout: 300000,
  }, async () => {
    const { page, problems } = await session.open('examples/web-component.html', { wait: false });
    await page.waitForFunction(() => customElements.get('ruled-view'));
    const report = await page.evaluate(async (count) => {
      const view = /** @type {any} */ (document.createElement('ruled-view'));
      view.setAttribute('height', '400');
      view.setAttribute('controls', '');
      document.body.append(view);
      /** @type {unknown[]} */
      const errors = [];
      view.addEventListener('error', (/** @type {CustomEvent} */ e) => errors.push(e.detail));
      // a hyperboloid of one sheet: ruling i from (cos u, sin u, −1) to (cos(u + 1.2), sin(u + 1.2), 1)
      const segments = new Float64Array(6 * count);
      for (let i = 0; i < count; i++) {
        const u = (2 * Math.PI * i) / count;
        segments.set([Math.cos(u), Math.sin(u), -1, Math.cos(u + 1.2), Math.sin(u + 1.2), 1], 6 * i);
      }
      // the page's longest pause: a timer due every 20 ms, and when it actually ran
      let last = performance.now();
      let longest = 0;
      const timer = setInterval(() => {
        const now = performance.now();
        longest = Math.max(longest, now - last);
        last = now;
      }, 20);
      const t0 = performance.now();
      view.data = { segments };
      await view.opening;
      // drawn: the readout counts the rulings and a frame has been drawn since
      const frames = Number(view.dataset.frames ?? 0);
      for (;;) {
        const counted = view.readouts?.().find((/** @type {{key: string}} */ r) => r.key === 'readout.rulings');
        if (counted?.value === count && Number(view.dataset.frames ?? 0) > frames) break;
        if (errors.length || performance.now() - t0 > 240000) break;
        await new Promise((r) => setTimeout(r, 20));
      }
      const seconds = (performance.now() - t0) / 1000;
      clearInterval(timer);
      const counted = view.readouts?.().find((/** @type {{key: string}} */ r) => r.key === 'readout.rulings');
      const note = view.shadowRoot?.querySelector('.rl-readout-note')?.textContent ?? '';
      return { seconds, longestPause: longest / 1000, counted: counted?.value, errors, note };
    }, n);
    mkdirSync(ARTIFACTS, { recursive: true });
    writeFileSync(`${ARTIFACTS}/million-${n}.json`, JSON.stringify(report, null, 1));
    console.log(
      `${n} rulings: drawn in ${report.seconds.toFixed(1)} s, longest pause ${report.longestPause.toFixed(1)} s`,
    );
    assert.deepEqual(report.errors, []);
    assert.equal(report.counted, n);
    assert.match(report.note, new RegExp(`one ruling in ${n / 20_000} is drawn \\(20,?001 of them\\)`));
    assert.deepEqual(problems, []);
    await page.close();
  });
}
