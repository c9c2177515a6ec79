// Where users put ruledlab: pages of another origin (a course system, a lecturer's site), into
// which a test pastes what ruledlab hands out, and checks of a view as a reader meets it there.
import { before, after } from 'node:test';
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { unzipSync } from '../../pkg/zip.js';
import { startServer } from '../../scripts/serve.mjs';
import { decodePng, countDifferent } from './png.mjs';

export const BACKGROUND = [251, 250, 247];

/**
 * A second origin for one test file: a server of a temporary folder, started before and closed
 * after its tests. `write(name, html, headers?)` puts a page there; `url + name` opens it;
 * `unpack(zip, name)` unzips a package (SCORM, H5P) into its folder `name`/ and gives its URL.
 */
export function otherOrigin() {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-site-'));
  /** @type {Record<string, Record<string, string>>} */
  const headersOf = {};
  const site = {
    url: '',
    dir,
    /** @param {string} name @param {string} html @param {Record<string, string>} [headers] */
    write(name, html, headers) {
      writeFileSync(join(dir, name), html);
      if (headers) headersOf[`/${name}`] = headers;
      return site.url + name;
    },
    /** @param {Uint8Array} bytes @param {string} name */
    unpack(bytes, name) {
      for (const [path, data] of Object.entries(unzipSync(bytes))) {
        const file = join(dir, name, path);
        mkdirSync(dirname(file), { recursive: true });
        writeFileSync(file, data);
      }
      return `${site.url}${name}/`;
    },
  };
  /** @type {import('node:http').Server | undefined} */
  let server;
  before(async () => {
    ({ server, url: site.url } = await startServer({ root: dir, headersFor: (path) => headersOf[path] ?? {} }));
  });
  after(() => server?.close());
  return site;
}

/** A plain page of a course system or site around `body` (a favicon, so Chromium asks for nothing). */
export function hostPage(/** @type {string} */ body, /** @type {string} */ head = '') {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course page</title>${head}</head><body style="margin: 16px; font: 16px serif"><p>Some course text above the figure.</p>${body}<p>And some below it.</p></body></html>`;
}

/** The share of a screenshot's pixels that differ from the page's paper colour. */
export function drawnShare(/** @type {Buffer} */ png) {
  const image = decodePng(png);
  return countDifferent(image, BACKGROUND) / (image.width * image.height);
}
