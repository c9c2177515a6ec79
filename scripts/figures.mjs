// The book's pictures (and the README's screenshot), made by the page itself: screenshots of the
// page and black-and-white figures exported with <ruled-view>.exportSVG({ bw: true }) — the same
// code a lecturer uses — and Fig. 2's TikZ export typeset by pdflatex (where it is installed:
// npm test's setup puts it there), turned into a PNG by pdftoppm. Run after a build:
// `node scripts/figures.mjs` (writes docs/src/images/).
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startServer } from './serve.mjs';

const IMAGES = new URL('../docs/src/images/', import.meta.url).pathname;

/**
 * the element's attributes (a scene and its params, or a figure of the paper), camera [yaw, pitch,
 * distance, tx, ty, tz] or null for the scene's own, file name
 * @type {[Record<string, string>, number[] | null, string][]}
 */
const FIGURES = [
  [{ scene: 'notation' }, null, 'figure-1-notation-bw.svg'],
  [{ scene: 'curves', params: 'w=1/13&steps=4' }, [-1.5707963, 1.45, 18, 4, 0.15, 0], 'figure-8-dlg-bw.svg'],
  [{ paper: 'fig2' }, null, 'figure-2-striction-bw.svg'],
  [{ paper: 'fig13' }, null, 'figure-13-sphere-bw.svg'],
];

/** Typesets a TikZ picture with pdflatex and saves its page as a PNG (skipped without pdflatex). */
function typeset(/** @type {string} */ tikz, /** @type {string} */ file) {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-tikz-'));
  // the page is the picture's box with a margin of 10 pt (pdflatex ships the box alone)
  const tex = [
    '\\documentclass{article}',
    '\\usepackage{tikz}',
    '\\begin{document}',
    `\\setbox0\\hbox{${tikz.trimEnd()}}`,
    '\\pdfpagewidth=\\dimexpr\\wd0+20pt\\relax \\pdfpageheight=\\dimexpr\\ht0+\\dp0+20pt\\relax',
    '\\pdfhorigin=10pt \\pdfvorigin=10pt \\shipout\\box0',
    '\\end{document}',
  ];
  writeFileSync(join(dir, 'figure.tex'), tex.join('\n'));
  try {
    execFileSync('pdflatex', ['-interaction=nonstopmode', '-halt-on-error', 'figure.tex'], {
      cwd: dir,
      stdio: 'ignore',
    });
    execFileSync('pdftoppm', ['-r', '110', '-png', '-singlefile', 'figure.pdf', 'figure'], { cwd: dir });
    writeFileSync(join(IMAGES, file), readFileSync(join(dir, 'figure.png')));
    console.log(`docs/src/images/${file}`);
  } catch (e) {
    console.log(`docs/src/images/${file} not made: ${/** @type {Error} */ (e).message.split('\n')[0]}`);
  }
}

const { server, url } = await startServer();
const context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'ruledlab-figures-')), {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1200, height: 800 },
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking'],
});
try {
  const page = await context.newPage();
  await page.goto(`${url}#scene=striction`);
  await page.waitForFunction(
    () => /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'))?.dataset.ready === '1',
  );
  await page.waitForTimeout(300);
  writeFileSync(join(IMAGES, 'screenshot-striction.png'), await page.screenshot());
  console.log('docs/src/images/screenshot-striction.png');
  for (const [hash, file] of [
    ['#scene=formula', 'screenshot-formula.png'],
    ['#scene=focal&congruence=example5&reach=1', 'screenshot-focal.png'],
    ['#scene=klein', 'screenshot-klein.png'],
    ['#scene=lines&klein', 'screenshot-klein-beside.png'],
  ]) {
    await page.goto(url + hash);
    await page.waitForFunction(
      () => /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'))?.dataset.ready === '1',
    );
    await page.waitForTimeout(300);
    writeFileSync(join(IMAGES, file), await page.screenshot());
    console.log(`docs/src/images/${file}`);
  }

  // editing: a ruling of the hyperboloid twisted by its end, the striction polygon following,
  // every handle shown (E), the moved one selected
  await page.goto(`${url}#scene=striction&n=24&normals=0`);
  await page.waitForFunction(
    () => /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'))?.dataset.ready === '1',
  );
  const grab = await page.evaluate(() => {
    const stage = /** @type {any} */ (window).ruledlab.stage;
    const r = stage.viewer.canvas.getBoundingClientRect();
    const m = stage.viewer.camera.viewProj(r.width / r.height);
    // ruling 16's end a, in front
    const [x, y, z] = stage.editor.handles()[32].world;
    const w = m[3] * x + m[7] * y + m[11] * z + m[15];
    return {
      x: r.left + (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * r.width,
      y: r.top + ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * r.height,
    };
  });
  await page.mouse.move(grab.x, grab.y);
  await page.mouse.down();
  await page.mouse.move(grab.x + 90, grab.y + 40, { steps: 8 });
  await page.mouse.up();
  await page.keyboard.press('e');
  await page.waitForTimeout(300);
  writeFileSync(join(IMAGES, 'screenshot-edit.png'), await page.screenshot());
  console.log('docs/src/images/screenshot-edit.png');

  await page.goto(`${url}examples/web-component.html`);
  for (const [attributes, camera, file] of FIGURES) {
    const { svg, tikz } = await page.evaluate(
      async ([attrs, cam]) => {
        document.body.replaceChildren();
        const v = /** @type {any} */ (document.createElement('ruled-view'));
        Object.assign(v.style, { width: '640px', height: '420px', display: 'block' });
        for (const [k, value] of Object.entries(attrs)) v.setAttribute(k, value);
        document.body.append(v);
        await new Promise((r) => v.addEventListener('scene-change', r, { once: true }));
        if (cam) v.view.viewer.camera.fromArray(cam);
        v.view.viewer.render();
        return { svg: v.exportSVG({ bw: true, legend: true }), tikz: v.exportTikZ({ bw: true }) };
      },
      /** @type {const} */ ([attributes, camera]),
    );
    writeFileSync(join(IMAGES, file), svg);
    console.log(`docs/src/images/${file}`);
    if (attributes.paper === 'fig2') typeset(tikz, 'figure-2-striction-bw-pdflatex.png');
  }
} finally {
  await context.close();
  server.close();
}
