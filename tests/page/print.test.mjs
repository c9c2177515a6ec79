// Figures that print, checked with the programs that read them. Every scene is exported as
// <ruled-view> exports it (English and German with the defaults, English with every switch on),
// in colour and in black and white:
// - the SVG has no piece of a line shorter than a pixel that splitting made (a piece that short
//   touching another piece of its own lines), and each export takes well under a second;
// - the TikZ of all of them (with every switch on: in black and white), one figure per page,
//   compiles with pdflatex and with lualatex
//   (nothing but \usepackage{tikz}) without an error or a missing character, and every page
//   draws (pdftoppm: pixels that are not white);
// - the SVGs convert to PDF with rsvg-convert without a warning, and every page draws.
// The documents and PDFs are kept in test-artifacts/print/ for people to look at.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { pageSession, ARTIFACTS } from './browser.mjs';
import { decodePng, countDifferent } from './png.mjs';

const run = promisify(execFile);
const session = pageSession();
const OUT = join(ARTIFACTS, 'print');

/**
 * @typedef {{name: string, svg: string, svgBw: string, tikz: string, tikzBw: string, ms: number}} Export
 */

/** Every scene's exports, one <ruled-view> of 640 × 420 after the other in one page. */
async function exportAll() {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  const exports = /** @type {Export[]} */ (
    await page.evaluate(async () => {
      const { SCENES } = await import(new URL('../www/index.js', location.href).href);
      const out = [];
      for (const scene of SCENES) {
        const allOn = scene.params
          .filter((/** @type {any} */ p) => p.type === 'checkbox')
          .map((/** @type {any} */ p) => `${p.key}=1`)
          .join('&');
        for (const [lang, params, name] of [
          ['en', '', `${scene.id}-en`],
          ['de', '', `${scene.id}-de`],
          ['en', allOn, `${scene.id}-all`],
        ]) {
          if (name.endsWith('-all') && !allOn) continue;
          document.body.replaceChildren();
          const v = /** @type {any} */ (document.createElement('ruled-view'));
          Object.assign(v.style, { width: '640px', height: '420px', display: 'block' });
          v.setAttribute('scene', scene.id);
          v.setAttribute('params', params);
          v.setAttribute('lang', lang);
          document.body.append(v);
          await new Promise((resolve) => v.addEventListener('scene-change', resolve, { once: true }));
          const t0 = performance.now();
          const svgBw = v.exportSVG({ bw: true });
          const ms = performance.now() - t0;
          out.push({
            name,
            ms,
            svgBw,
            svg: v.exportSVG(),
            tikz: v.exportTikZ(),
            tikzBw: v.exportTikZ({ bw: true }),
          });
        }
      }
      return out;
    })
  );
  // splitting artefacts: a polyline shorter than a pixel that touches another of its set
  const artefacts = await page.evaluate(
    (svgs) =>
      svgs.flatMap(([name, text]) => {
        const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
        /** @type {Map<string, number[][]>} */
        const sets = new Map();
        for (const line of doc.querySelectorAll('g.lines > polyline')) {
          const set = /** @type {string} */ (/** @type {Element} */ (line.parentNode).getAttribute('class'))
            .split(' ')
            .find((c) => c.startsWith('set-'));
          const points = /** @type {string} */ (line.getAttribute('points'))
            .split(' ')
            .map((p) => p.split(',').map(Number));
          sets.set(/** @type {string} */ (set), [...(sets.get(/** @type {string} */ (set)) ?? []), points.flat()]);
        }
        const found = [];
        for (const [set, lines] of sets) {
          const ends = lines.map((p) => [p.slice(0, 2), p.slice(-2)]);
          lines.forEach((p, k) => {
            let length = 0;
            for (let i = 2; i < p.length; i += 2) length += Math.hypot(p[i] - p[i - 2], p[i + 1] - p[i - 1]);
            if (length >= 1) return;
            const touches = ends.some(
              (e, j) => j !== k && e.some((q) => ends[k].some((r) => Math.hypot(q[0] - r[0], q[1] - r[1]) < 0.02)),
            );
            if (touches) found.push(`${name} ${set}: a piece of ${length.toFixed(2)} px at ${p.slice(0, 2)}`);
          });
        }
        return found;
      }),
    exports.flatMap((e) => [
      [`${e.name} colour`, e.svg],
      [`${e.name} bw`, e.svgBw],
    ]),
  );
  assert.deepEqual(problems, []);
  await page.close();
  return { exports, artefacts };
}

/** Pages of a PDF as images at `dpi`, and the number of pixels of each that are not white. */
async function pages(/** @type {string} */ pdf, dpi = 18) {
  const base = `${pdf.replace(/\.pdf$/, '')}-page`;
  await run('pdftoppm', ['-r', String(dpi), '-png', join(OUT, pdf), join(OUT, base)]);
  return readdirSync(OUT)
    .filter((f) => f.startsWith(base) && f.endsWith('.png'))
    .sort()
    .map((f) => countDifferent(decodePng(readFileSync(join(OUT, f))), [255, 255, 255], 24));
}

test('every scene prints: SVG without splitting slivers, TikZ through pdflatex and lualatex, SVG through rsvg-convert', async () => {
  const t0 = Date.now();
  rmSync(OUT, { recursive: true, force: true });
  mkdirSync(OUT, { recursive: true });
  const { exports, artefacts } = await exportAll();
  const exported = Date.now();
  assert.ok(exports.length >= 30, `only ${exports.length} views`);
  assert.deepEqual(artefacts, [], 'pieces of lines shorter than a pixel made by splitting');
  for (const e of exports) assert.ok(e.ms < 1000, `${e.name}: the black-and-white SVG took ${e.ms.toFixed(0)} ms`);
  const slowest = [...exports].sort((a, b) => b.ms - a.ms).slice(0, 4);
  console.log(
    `# SVG export (black and white), slowest: ${slowest.map((e) => `${e.name} ${e.ms.toFixed(0)} ms`).join(', ')}`,
  );

  // TikZ: one document, one figure per page, for each engine; both engines at once
  // (the views with every switch on in black and white only: their colour differs in nothing new)
  const figures = exports.flatMap((e) => [
    ...(e.name.endsWith('-all') ? [] : [[e.name, e.tikz]]),
    [`${e.name} bw`, e.tikzBw],
  ]);
  for (const [name, tikz] of figures) assert.match(tikz, /^[\x20-\x7e\n]*$/, `${name}: TikZ is not pure ASCII`);
  const document = [
    '\\documentclass{article}',
    '\\usepackage{tikz}',
    '\\pagestyle{empty}',
    '\\tracinglostchars=2',
    '\\begin{document}',
    ...figures.map(([name, tikz]) => `% ${name}\n\\noindent\n${tikz}\\clearpage`),
    '\\end{document}',
    '',
  ].join('\n');
  const engines = ['pdflatex', 'lualatex'];
  for (const engine of engines) writeFileSync(join(OUT, `figures-${engine}.tex`), document);
  const svgFiles = exports.flatMap((e) =>
    [
      [`${e.name}.svg`, e.svg],
      [`${e.name}-bw.svg`, e.svgBw],
    ].map(([file, text]) => {
      writeFileSync(join(OUT, file), text);
      return join(OUT, file);
    }),
  );
  const [latex, rsvg] = await Promise.all([
    Promise.all(
      engines.map((engine) =>
        run(engine, ['-interaction=nonstopmode', '-halt-on-error', `figures-${engine}.tex`], {
          cwd: OUT,
          maxBuffer: 1 << 26,
          timeout: 600_000,
        }).catch((e) => ({ stdout: String(e.stdout), stderr: `${engine} failed: ${e.message}` })),
      ),
    ),
    run('rsvg-convert', ['-f', 'pdf', '-o', join(OUT, 'figures-svg.pdf'), ...svgFiles], { maxBuffer: 1 << 26 }),
  ]);
  const compiled = Date.now();
  engines.forEach((engine, k) => {
    const log = readFileSync(join(OUT, `figures-${engine}.log`), 'utf8');
    assert.equal(latex[k].stderr, '', `${engine}: ${latex[k].stderr}`);
    assert.doesNotMatch(log, /^! /m, `${engine} reports an error (test-artifacts/print/figures-${engine}.log)`);
    assert.doesNotMatch(log, /Missing character/, `${engine} misses a character`);
  });
  assert.equal(rsvg.stderr, '', `rsvg-convert: ${rsvg.stderr}`);
  for (const pdf of [...engines.map((e) => `figures-${e}.pdf`), 'figures-svg.pdf']) {
    const inked = await pages(pdf);
    const expected = pdf === 'figures-svg.pdf' ? svgFiles.length : figures.length;
    assert.equal(inked.length, expected, `${pdf}: ${inked.length} pages`);
    inked.forEach((n, k) => {
      assert.ok(n > 150, `${pdf}, page ${k + 1}: only ${n} pixels drawn`);
    });
  }
  console.log(
    `# ${exports.length} views exported in ${((exported - t0) / 1000).toFixed(1)} s; ${figures.length} TikZ figures through ${engines.join(' and ')} and ${svgFiles.length} SVGs through rsvg-convert in ${((compiled - exported) / 1000).toFixed(1)} s; all in ${((Date.now() - t0) / 1000).toFixed(1)} s`,
  );
});
