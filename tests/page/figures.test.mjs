// Figures for lecture notes: SVG that parses and holds what the view shows (labels as <text>),
// black and white without colour, TikZ of a known view equal to the checked-in file, PNG at 2×
// and 4× with labels and legend, and the page's export buttons: names that say what the figure
// is (Fig. 13 and Fig. 15 do not overwrite each other), the printed width the reader chooses,
// line widths and dashes the same on paper at any width.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { pageSession } from './browser.mjs';
import { countDifferent, decodePng } from './png.mjs';

const BACKGROUND = [251, 250, 247];

const session = pageSession();
const EXPECTED = new URL('./expected/curves-fig8.tikz', import.meta.url);

/** A page with one <ruled-view> of fixed size showing `scene` with `params` and a fixed camera. */
async function element(scene, params, camera) {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await page.evaluate(
    async ([s, q, cam]) => {
      document.body.replaceChildren();
      const v = document.createElement('ruled-view');
      v.id = 'figure';
      Object.assign(v.style, { width: '640px', height: '420px', display: 'block' });
      v.setAttribute('scene', s);
      v.setAttribute('params', q);
      document.body.append(v);
      await new Promise((r) => v.addEventListener('scene-change', r, { once: true }));
      v.view.viewer.camera.fromArray(cam);
      v.view.viewer.render();
    },
    [scene, params, camera],
  );
  return { page, problems };
}

test('SVG: parses, holds the segments of the view, labels as <text> with subscripts; black and white has no colour', async () => {
  const { page, problems } = await element('notation', '', [-0.9, 0.25, 4.5, 0, 0, 0]);
  const svg = await page.evaluate(() => document.getElementById('figure').exportSVG());
  const counts = await page.evaluate((text) => {
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    return {
      error: doc.querySelector('parsererror')?.textContent ?? '',
      root: doc.documentElement.namespaceURI,
      lines: doc.querySelectorAll('g.visible > g.lines > polyline').length,
      legend: doc.querySelectorAll('g.legend > line').length,
      texts: [...doc.querySelectorAll('g[font-style="italic"] > g:not([stroke]) > text')].map((t) => t.textContent),
      halos: doc.querySelectorAll('g[font-style="italic"] > g[stroke] > text').length,
      subscripts: doc.querySelectorAll('g[font-style="italic"] > g:not([stroke]) > text tspan[font-size]').length,
      styles: doc.querySelectorAll('style, link, image, foreignObject').length,
    };
  }, svg);
  assert.equal(counts.error, '');
  assert.equal(counts.root, 'http://www.w3.org/2000/svg');
  // 3 rulings, 2 common perpendiculars, 1 parallel through f_{i,i+1} (no surface hides them);
  // 3 legend lines
  assert.equal(counts.lines, 6);
  assert.equal(counts.legend, 3);
  assert.deepEqual(
    counts.texts.sort(),
    ['Ri', 'Ri+1', 'Ri−1', 'fi+1,i', 'fi,i+1', 'fi,i−1', 'mi', 'Ni,i+1, hi,i+1', 'φi,i+1'].sort(),
  );
  assert.ok(counts.subscripts >= 9);
  assert.equal(counts.halos, counts.texts.length, 'every label has a halo drawn under it');
  assert.equal(counts.styles, 0, 'self-contained: no stylesheet, link or image');
  const bw = await page.evaluate(() => document.getElementById('figure').exportSVG({ bw: true, title: true }));
  const colours = [...bw.matchAll(/(?:stroke|fill)="(#[0-9a-f]{6})"/g)].map((m) => m[1]);
  const coloured = colours.filter((c) => !(c.slice(1, 3) === c.slice(3, 5) && c.slice(3, 5) === c.slice(5, 7)));
  assert.deepEqual([...new Set(coloured)], [], 'black and white uses greys only');
  assert.match(bw, /Notation: angle, perpendicular, footpoints \(Fig\. 1\)/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('TikZ of a known view equals the checked-in file; labels come out as math', async () => {
  const { page, problems } = await element(
    'curves',
    'w=0.07692307692307693&steps=2',
    [-1.5707963, 1.45, 18, 4, 0.15, 0],
  );
  const tikz = await page.evaluate(() => document.getElementById('figure').exportTikZ({ bw: true }));
  if (process.env.UPDATE_EXPECTED || !existsSync(EXPECTED)) writeFileSync(EXPECTED, tikz);
  assert.equal(tikz, readFileSync(EXPECTED, 'utf8'));
  assert.match(tikz, /^% Curve subdivision \(Figs\. 7-8\): exported by ruledlab/);
  assert.match(tikz, /^[\x20-\x7e\n]*$/, 'pure ASCII');
  assert.match(tikz, /\\begin\{tikzpicture\}[\s\S]*\\draw\[[\s\S]*\\end\{tikzpicture\}/);
  await page.evaluate(() => (document.getElementById('figure').scene = 'notation'));
  await page.waitForFunction(() => document.getElementById('figure').view.scene.id === 'notation');
  await page.waitForTimeout(300);
  const notation = await page.evaluate(() => document.getElementById('figure').exportTikZ());
  assert.match(notation, /\{\$R_\{i\+1\}\$\}/);
  // the legend: symbols as math, one entry hanging from the one above
  assert.match(notation, /\{common perpendiculars \$N_\{i,i\+1\}\$ and footpoints\}/);
  assert.match(notation, /\(rl-legend-1\) at \(rl-legend-0\.south west\)/);
  assert.match(notation, /\{\$\\varphi_\{i,i\+1\}\$\}/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('PNG at 2× and 4× of the view, and the page’s export buttons download figures', async () => {
  const { page, problems } = await element('striction', '', [-0.9, 0.45, 15, 0, 0, 0]);
  // 1× too: a figure's frame is drawn afresh (at the view's own size the frame the canvas showed
  // was resolved again, and Chromium's drawImage read the canvas as black)
  for (const scale of [1, 2, 4]) {
    const bytes = await page.evaluate(
      async (s) => [
        ...new Uint8Array(await (await document.getElementById('figure').exportPNG({ scale: s })).arrayBuffer()),
      ],
      scale,
    );
    const image = decodePng(Buffer.from(bytes));
    assert.deepEqual([image.width, image.height], [640 * scale, 420 * scale]);
    assert.ok(
      countDifferent(image, BACKGROUND) < 0.5 * image.width * image.height,
      `the ${scale}× PNG is the view, on its background`,
    );
    assert.ok(
      countDifferent(image, BACKGROUND) > 0.005 * image.width * image.height,
      `the ${scale}× PNG shows the scene`,
    );
  }
  await page.close();
  const { page: p, problems: figureProblems } = await session.open('#scene=convergence');
  await p.locator('.io summary').click();
  for (const [kind, name] of [
    ['svg', 'convergence-levels8.svg'],
    ['svgBw', 'convergence-levels8-bw.svg'],
    ['tikz', 'convergence-levels8.tikz'],
    ['tikzBw', 'convergence-levels8-bw.tikz'],
    ['png2', 'convergence-levels8-2x.png'],
    ['plot', 'convergence-levels8-plot.svg'],
  ]) {
    const [download] = await Promise.all([p.waitForEvent('download'), p.locator(`[data-export="${kind}"]`).click()]);
    assert.equal(download.suggestedFilename(), name);
  }
  // the convergence plot is self-contained: its own grid, dashed slopes and legend
  const plot = await p.evaluate(() => new XMLSerializer().serializeToString(document.querySelector('.rl-figure svg')));
  assert.match(plot, /stroke-dasharray="4 3"/);
  assert.doesNotMatch(plot, /class="/);
  assert.deepEqual(problems, []);
  assert.deepEqual(figureProblems, []);
  await p.close();
  // the data files, as a user saves them: a surface's, then a congruence's (no invariants). A
  // page of their own: Chromium 156 holds back the 11th download of one page in quick succession
  // (it would ask a user whether the site may download several files), so one page does not
  // save all 11
  const { page: d, problems: dataProblems } = await session.open('#scene=convergence');
  await d.locator('.io summary').click();
  const save = async (/** @type {string} */ kind) => {
    const [download] = await Promise.all([d.waitForEvent('download'), d.locator(`[data-export="${kind}"]`).click()]);
    return {
      name: download.suggestedFilename(),
      text: readFileSync(/** @type {string} */ (await download.path()), 'utf8'),
    };
  };
  await d.evaluate(() => {
    location.hash = '#scene=striction';
  });
  await d.locator('[data-export="obj"]:not([disabled])').waitFor();
  const obj = await save('obj');
  assert.equal(obj.name, 'striction-n36.obj');
  assert.match(obj.text, /^o striction\n(v \S+ \S+ \S+\n)+(l \d+ \d+\n)+(f \d+ \d+ \d+ \d+\n)+$/m);
  const inv = await save('invariants');
  assert.equal(inv.name, 'striction-n36-invariants.json');
  assert.ok(JSON.parse(inv.text).distribution.length > 2);
  assert.match((await save('invariantsCsv')).text, /^pair,angle,distance,distribution,/);
  await d.evaluate(() => {
    location.hash = '#scene=congruence';
  });
  await d.locator('[data-export="invariants"][disabled]').waitFor();
  const lines = await save('obj');
  assert.doesNotMatch(lines.text, /^f /m);
  assert.equal(JSON.parse((await save('json')).text).rows > 1, true);
  assert.deepEqual(dataProblems, []);
  await d.close();
});

/** Saves the export `kind` of the page's view: its suggested name and its text. */
async function save(/** @type {import('playwright-core').Page} */ page, /** @type {string} */ kind) {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.locator(`[data-export="${kind}"]`).click(),
  ]);
  return {
    name: download.suggestedFilename(),
    text: readFileSync(/** @type {string} */ (await download.path()), 'utf8'),
  };
}

/** Follows `hash` in the page and waits until `scene` is computed and drawn. */
async function follow(
  /** @type {import('playwright-core').Page} */ page,
  /** @type {string} */ hash,
  /** @type {string} */ scene,
) {
  await page.evaluate((h) => {
    location.hash = h;
  }, hash);
  await page.locator(`.rl-stage[data-scene="${scene}"][data-ready="1"]`).waitFor();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

test('export names say what the figure is: Fig. 13 and Fig. 15 apart, the counts, a switch, the language', async () => {
  const { page, problems } = await session.open('#paper=fig13');
  await page.locator('.io summary').click();
  const fig13 = await save(page, 'svgBw');
  assert.equal(fig13.name, 'fig13-congruence-bw.svg');
  await follow(page, '#paper=fig15', 'congruence');
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.paper?.id === 'fig15');
  const fig15 = await save(page, 'svgBw');
  assert.equal(fig15.name, 'fig15-congruence-bw.svg');
  assert.notEqual(fig13.text, fig15.text);
  await follow(page, '#scene=striction', 'striction');
  assert.equal((await save(page, 'tikzBw')).name, 'striction-n36-bw.tikz');
  await follow(page, '#scene=striction&exact=1&lang=de', 'striction');
  await page.waitForFunction(() => document.documentElement.lang === 'de');
  assert.equal((await save(page, 'svg')).name, 'striction-n36-exact-de.svg');
  assert.equal((await save(page, 'csv')).name, 'striction-n36-exact.csv', 'a data file has no words: no language');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the printed width: the SVG is as wide as chosen (8 cm by default), its lines and dashes the same on paper at any width', async () => {
  const { page, problems } = await session.open('#paper=fig2');
  await page.locator('.io summary').click();
  assert.equal(await page.locator('#print-width').inputValue(), '8');
  /** The width on paper (mm), and the stroke width and dashes of the common perpendiculars (mm). */
  const measure = (/** @type {string} */ text) =>
    page.evaluate((svg) => {
      const root = new DOMParser().parseFromString(svg, 'image/svg+xml').documentElement;
      const mm = Number.parseFloat(/** @type {string} */ (root.getAttribute('width')));
      const perMm = Number(/** @type {string} */ (root.getAttribute('viewBox')).split(' ')[2]) / mm;
      const group = /** @type {Element} */ (root.querySelector('g.visible > g.lines.normal'));
      const dashes = (/** @type {Element} */ e) =>
        /** @type {string} */ (e.getAttribute('stroke-dasharray')).split(' ').map((d) => Number(d) / perMm);
      return {
        mm,
        stroke: Number(group.getAttribute('stroke-width')) / perMm,
        dash: dashes(group),
        // a piece too short for the style's dashes: its own, shorter pattern
        short: [...group.querySelectorAll('polyline[stroke-dasharray]')].map(dashes),
      };
    }, text);
  const column = await measure((await save(page, 'svgBw')).text);
  assert.equal(column.mm, 80);
  await page.locator('#print-width').fill('16');
  const wide = await measure((await save(page, 'svgBw')).text);
  assert.equal(wide.mm, 160);
  // 0.6 × 1.6 px of the screen (0.75 pt each) on paper: 0.254 mm, at 8 cm and at 16 cm
  for (const m of [column, wide]) {
    assert.ok(Math.abs(m.stroke - 0.96 * (25.4 / 96)) < 0.002, `stroke ${m.stroke} mm`);
    assert.deepEqual(
      m.dash.map((d) => Math.round(d * 100) / 100),
      [0.79, 0.53],
    );
  }
  // in the column, Fig. 2's shortest common perpendiculars get shorter dashes — none below 0.2 mm
  assert.ok(column.short.length > 0, 'no short perpendicular got a pattern of its own');
  for (const d of column.short.flat()) assert.ok(d >= 0.2 && d < 0.79, `a dash of ${d} mm`);
  // a width out of range is brought into it, and the field shows what was used
  await page.locator('#print-width').fill('400');
  assert.equal((await measure((await save(page, 'svgBw')).text)).mm, 400);
  assert.equal(await page.locator('#print-width').inputValue(), '40');
  assert.deepEqual(problems, []);
  await page.close();
});
