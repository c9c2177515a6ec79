// Figures for lecture notes: SVG that parses and holds what the view shows (labels as <text>),
// black and white without colour, TikZ of a known view equal to the checked-in file, PNG at 2×
// and 4× with labels and legend, and the page's export buttons.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { pageSession } from './browser.mjs';
import { decodePng } from './png.mjs';

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
  for (const scale of [2, 4]) {
    const bytes = await page.evaluate(
      async (s) => [
        ...new Uint8Array(await (await document.getElementById('figure').exportPNG({ scale: s })).arrayBuffer()),
      ],
      scale,
    );
    const image = decodePng(Buffer.from(bytes));
    assert.deepEqual([image.width, image.height], [640 * scale, 420 * scale]);
  }
  await page.close();
  const { page: p, problems: figureProblems } = await session.open('#scene=convergence');
  await p.locator('.io summary').click();
  for (const [kind, name] of [
    ['svg', /convergence\.svg$/],
    ['svgBw', /convergence-bw\.svg$/],
    ['tikz', /convergence\.tikz$/],
    ['tikzBw', /convergence-bw\.tikz$/],
    ['png2', /convergence-2x\.png$/],
    ['plot', /convergence-plot\.svg$/],
  ]) {
    const [download] = await Promise.all([p.waitForEvent('download'), p.locator(`[data-export="${kind}"]`).click()]);
    assert.match(download.suggestedFilename(), name);
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
  assert.equal(obj.name, 'striction.obj');
  assert.match(obj.text, /^o striction\n(v \S+ \S+ \S+\n)+(l \d+ \d+\n)+(f \d+ \d+ \d+ \d+\n)+$/m);
  const inv = await save('invariants');
  assert.equal(inv.name, 'striction-invariants.json');
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
