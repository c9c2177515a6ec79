// Many rulings given to <ruled-view> as data, as the notebook's View.from_segments sends them (a
// Float64Array, six numbers a ruling): 100 000 and 10⁶ are drawn with no error and counted in the
// readout, at the level of detail the view says (above 20 000 rulings the strip and the striction
// curve through every k-th ruling, 2 001 of them, and at most 160 rulings as lines; the numbers
// of all), the invariants computed in the page's worker, not on its thread (no measure of them in
// the page's timeline); how long that took (to the frame after the invariants came) and
// the page's longest pause meanwhile are reported (speed is measured, not judged: the times go to
// the artifacts and the book, never into an assertion). Drawing every ruling's strip, lines,
// normals, points and handles had taken 26 s for 100 000 rulings and more than 5 minutes for 10⁶
// in the test machine's software WebGL (SwiftShader), nearly all of it native drawing. The
// reductions that failed from about 125 000 rulings are tested in Node (tests/node/spreads.test.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { pageSession, ARTIFACTS } from './browser.mjs';

const session = pageSession();

/**
 * A page with one <ruled-view controls> 400 px high, and `hyperboloid(count)` in it: `count`
 * rulings of a hyperboloid of one sheet, ruling i from (cos u, sin u, −1) to
 * (cos(u + 1.2), sin(u + 1.2), 1) with u = 2πi/count.
 */
async function openView() {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await page.waitForFunction(() => customElements.get('ruled-view'));
  await page.evaluate(() => {
    const view = document.createElement('ruled-view');
    view.setAttribute('height', '400');
    view.setAttribute('controls', '');
    document.body.append(view);
    /** @type {any} */ (window).hyperboloid = (/** @type {number} */ count) => {
      const segments = new Float64Array(6 * count);
      for (let i = 0; i < count; i++) {
        const u = (2 * Math.PI * i) / count;
        segments.set([Math.cos(u), Math.sin(u), -1, Math.cos(u + 1.2), Math.sin(u + 1.2), 1], 6 * i);
      }
      return segments;
    };
  });
  return { page, problems };
}

for (const n of [100_000, 1_000_000]) {
  test(`a <ruled-view> given ${n.toLocaleString('en')} rulings as data draws them without an error`, {
    timeout: 300000,
  }, async () => {
    const { page, problems } = await openView();
    const report = await page.evaluate(async (count) => {
      const view = /** @type {any} */ (document.querySelector('ruled-view'));
      /** @type {unknown[]} */
      const errors = [];
      view.addEventListener('error', (/** @type {CustomEvent} */ e) => errors.push(e.detail));
      const segments = /** @type {any} */ (window).hyperboloid(count);
      // the page's longest pause: a timer due every 20 ms, and when it actually ran
      let last = performance.now();
      let longest = 0;
      const timer = setInterval(() => {
        const now = performance.now();
        longest = Math.max(longest, now - last);
        last = now;
      }, 20);
      const readout = (/** @type {string} */ key) =>
        view.readouts?.().find((/** @type {{key: string}} */ r) => r.key === key)?.value;
      const noteText = () => view.shadowRoot?.querySelector('.rl-readout-note')?.textContent ?? '';
      const description = () => view.shadowRoot?.querySelector('canvas')?.getAttribute('aria-describedby');
      performance.clearMeasures();
      const t0 = performance.now();
      view.data = { segments };
      await view.opening;
      // done: the readout counts the parallel pairs (the invariants have come from the worker),
      // and a frame has been drawn since it was last seen without them
      let before = Number(view.dataset.frames ?? 0);
      for (;;) {
        const frames = Number(view.dataset.frames ?? 0);
        if (readout('readout.parallelPairs') !== 0) before = frames;
        else if (frames > before) break;
        if (errors.length || performance.now() - t0 > 240000) break;
        await new Promise((r) => setTimeout(r, 20));
      }
      const seconds = (performance.now() - t0) / 1000;
      clearInterval(timer);
      const id = description();
      const said = (id && view.shadowRoot?.getElementById(id)?.textContent) || '';
      return {
        seconds,
        longestPause: longest / 1000,
        counted: readout('readout.rulings'),
        parallel: readout('readout.parallelPairs'),
        errors,
        note: noteText(),
        said,
        legend: [...(view.shadowRoot?.querySelectorAll('.rl-legend li') ?? [])].map((li) => li.textContent),
        // the invariants of these rulings computed on the page's own thread would leave this
        // measure, of 10 ms and more; the element's first scene (five rulings, before the data
        // came, on a busy machine after the measures were cleared) leaves one of microseconds
        onPage: performance.getEntriesByName('ruledlab:core:RuledSurface.invariants').filter((e) => e.duration > 5)
          .length,
      };
    }, n);
    mkdirSync(ARTIFACTS, { recursive: true });
    writeFileSync(`${ARTIFACTS}/million-${n}.json`, JSON.stringify(report, null, 1));
    console.log(
      `${n} rulings: drawn in ${report.seconds.toFixed(1)} s, longest pause ${report.longestPause.toFixed(1)} s`,
    );
    assert.deepEqual(report.errors, []);
    assert.equal(report.counted, n);
    assert.equal(report.parallel, 0);
    assert.equal(report.onPage, 0, 'no invariants computed on the page');
    assert.match(
      report.said,
      /drawn at a level of detail with its striction curve; the smallest \|δ\| of a pair of rulings is/,
    );
    assert.deepEqual(report.legend, ['your rulings', 'striction curve, through the rulings drawn']);
    assert.doesNotMatch(report.note, /being computed/);
    // 2 001 rulings through the strip (every k-th and the last), every 13th of them as a line
    const every = n / 2_000;
    const digits = (/** @type {number} */ x) => x.toLocaleString('en').replace(',', ',?');
    assert.match(
      report.note,
      new RegExp(
        `through one ruling in ${digits(every)} \\(2,?001 of them\\), and one ruling in ${digits(13 * every)} is`,
      ),
    );
    // the Klein view beside: 100 000 lines as points of M; more, a note in its place, no context
    const klein = await page.evaluate(async () => {
      const view = /** @type {any} */ (document.querySelector('ruled-view'));
      view.klein = true;
      const box = view.shadowRoot.querySelector('.rl-klein');
      const note = box.querySelector('.rl-klein-note');
      const t0 = performance.now();
      while (!Number(box.dataset.frames ?? 0) && note.hidden && performance.now() - t0 < 120000)
        await new Promise((r) => setTimeout(r, 50));
      return {
        frames: Number(box.dataset.frames ?? 0),
        note: note.hidden ? '' : note.textContent,
        canvas: !!box.querySelector('canvas:not([hidden])'),
      };
    });
    if (n <= 100_000) assert.ok(klein.frames > 0 && klein.canvas && klein.note === '', JSON.stringify(klein));
    else {
      assert.match(klein.note, /^1,000,000 lines: more than the Klein view draws \(100,000\)\.$/);
      assert.equal(klein.canvas, false);
    }
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test('Cancel while the invariants of 10⁶ rulings are computed: the rulings stay, and the view says they were not computed', {
  timeout: 300000,
}, async () => {
  const { page, problems } = await openView();
  const report = await page.evaluate(async (count) => {
    const view = /** @type {any} */ (document.querySelector('ruled-view'));
    view.data = { segments: /** @type {any} */ (window).hyperboloid(count) };
    await view.opening;
    const root = view.shadowRoot;
    const progress = root.querySelector('.rl-progress');
    const pending = { progress: !progress.hidden, note: root.querySelector('.rl-readout-note')?.textContent ?? '' };
    progress.querySelector('button').click();
    // well past when the worker would have answered
    await new Promise((r) => setTimeout(r, 3000));
    const id = root.querySelector('canvas')?.getAttribute('aria-describedby');
    return {
      pending,
      progress: !progress.hidden,
      note: root.querySelector('.rl-readout-note')?.textContent ?? '',
      said: (id && root.getElementById(id)?.textContent) || '',
      keys: view.readouts().map((/** @type {{key: string}} */ r) => r.key),
      frames: Number(view.dataset.frames ?? 0),
    };
  }, 1_000_000);
  assert.equal(report.pending.progress, true, 'the progress bar while the worker computes');
  assert.match(report.pending.note, /being computed in the background/);
  assert.equal(report.progress, false);
  assert.match(report.note, /were not computed \(cancelled\)/);
  assert.doesNotMatch(report.note, /being computed/);
  assert.match(report.said, /its invariants were not computed \(cancelled\)/);
  assert.deepEqual(report.keys, ['readout.rulings']);
  assert.ok(report.frames > 0, 'the rulings are drawn');
  assert.deepEqual(problems, []);
  await page.close();
});
