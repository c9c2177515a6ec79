// The paper-models scene's downloads as a reader clicks them: the sheet as SVG (1:1 in mm, the
// check square) and DXF, and the sheet tiled on A4 pages, a zip of one SVG a page whose library
// loads only then.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { pageSession, ready } from './browser.mjs';
import { unzipSync, strFromU8 } from '../../pkg/zip.js';

const session = pageSession();

test('the paper-models scene hands out its pattern as SVG, DXF and A4 pages, as clicked', async () => {
  const { page, problems } = await session.open('index.html#scene=developable&kind=cone&n=24');
  await ready(page);
  /** The file the button named `name` downloads. @param {RegExp} name */
  const download = async (name) => {
    const [file] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name }).click()]);
    return { name: file.suggestedFilename(), bytes: readFileSync(/** @type {string} */ (await file.path())) };
  };
  const svg = await download(/SVG, 1:1/);
  assert.equal(svg.name, 'pattern-cone.svg');
  assert.match(svg.bytes.toString('utf8'), /<rect id="check-square" [^>]*width="100" height="100"/);
  const dxf = await download(/DXF R12/);
  assert.equal(dxf.name, 'pattern-cone.dxf');
  assert.match(dxf.bytes.toString('utf8'), /LAYER\n {2}2\nCUT\n/);
  const pages = await download(/A4 pages/);
  assert.equal(pages.name, 'pattern-cone-a4.zip');
  const files = unzipSync(new Uint8Array(pages.bytes));
  assert.ok(Object.keys(files).length >= 1 && Object.keys(files)[0] === 'page-01.svg');
  for (const svgPage of Object.values(files)) assert.match(strFromU8(svgPage), /width="210mm" height="297mm"/);
  assert.deepEqual(problems, []);
  await page.close();
});
