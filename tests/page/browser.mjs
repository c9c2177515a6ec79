// Launching Debian's Chromium through playwright-core, and watching a page for problems.
import { before, after } from 'node:test';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { decodePng } from './png.mjs';

/** @typedef {import('playwright-core').Page} Page */
/** @typedef {import('playwright-core').BrowserContext} BrowserContext */

export const ARTIFACTS = new URL('../../test-artifacts/', import.meta.url).pathname;

/**
 * A fresh headless Chromium (fresh profile, no network chatter); `options` may set another
 * viewport, or a phone: { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true }.
 */
export async function launch(options = {}) {
  const userDataDir = mkdtempSync(join(tmpdir(), 'ruledlab-chromium-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1200, height: 800 },
    ...options,
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
    ],
  });
  // npm test runs the page tests beside builds on 2 cores: a page may take longer to load, or a
  // wait to end, than Playwright's 30 s by default (a limit of time, not a check)
  context.setDefaultNavigationTimeout(120_000);
  context.setDefaultTimeout(90_000);
  return context;
}

/**
 * Records console errors, page errors, failed requests and HTTP errors of `page`.
 * @param {Page} page
 */
export function watch(page) {
  /** @type {string[]} */
  const problems = [];
  page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  page.on('response', (r) => r.status() >= 400 && problems.push(`HTTP ${r.status()}: ${r.url()}`));
  return problems;
}

/**
 * Screenshot of what WebGL drew, decoded: the overlays on the canvas (legend, hint) are
 * hidden for it, so a canvas that drew nothing really looks empty. The whole page, overlays
 * and text included, is saved as `<name>.png` for people to look at.
 */
/**
 * @param {Page} page
 * @param {string} name
 */
export async function shoot(page, name) {
  mkdirSync(ARTIFACTS, { recursive: true });
  writeFileSync(join(ARTIFACTS, `${name}.png`), await page.screenshot());
  await page.evaluate(() =>
    document.querySelectorAll('.rl-view > :not(canvas)').forEach((e) => {
      e.classList.add('rl-test-hidden');
    }),
  );
  await page.evaluate(() => {
    for (const e of document.querySelectorAll('.rl-test-hidden')) {
      const box = /** @type {HTMLElement} */ (e);
      box.style.visibility = 'hidden';
    }
  });
  const png = await page.locator('.rl-view canvas').first().screenshot();
  await page.evaluate(() => {
    for (const e of document.querySelectorAll('.rl-test-hidden')) {
      /** @type {HTMLElement} */ (e).style.visibility = '';
      e.classList.remove('rl-test-hidden');
    }
  });
  return decodePng(png);
}

/**
 * Waits until the page's stage has shown its final picture (worker results included).
 * @param {Page} page
 */
export async function ready(page, timeout = 30000) {
  // (the numbers final, and the first frame drawn: the viewer readies it off the page's tasks)
  await page.waitForFunction(
    () => {
      const stage = /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'));
      return stage?.dataset.ready === '1' && !!stage.querySelector('canvas')?.dataset.detail;
    },
    null,
    { timeout },
  );
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/**
 * The control of parameter `key` in the page's panel.
 * @param {Page} page
 * @param {string} key
 */
export function control(page, key) {
  return page.locator(`.rl-controls [name="${key}"]`);
}

/**
 * Sets a slider (or text field) of the page to `value` and waits for the new picture.
 * @param {Page} page
 * @param {string} key
 * @param {string | number | boolean} value   a boolean ticks a checkbox; a select takes its option
 */
export async function setControl(page, key, value) {
  const frames = await page.evaluate(() => Number(document.body.dataset.frames ?? 0));
  const input = control(page, key);
  const tag = await input.evaluate((e) => e.tagName);
  if (typeof value === 'boolean') await input.setChecked(value);
  else if (tag === 'SELECT') await input.selectOption(String(value));
  else await input.fill(String(value));
  await input.dispatchEvent('change');
  await framesAfter(page, frames);
}

/** How many animation frames the page runs in `ms` milliseconds (0–1 when its main thread is blocked). */
/** @param {Page} page */
export function animationFrames(page, ms = 500) {
  return page.evaluate(
    (span) =>
      new Promise((resolve) => {
        let n = 0;
        const t0 = performance.now();
        const tick = () => {
          if (performance.now() - t0 >= span) return resolve(n);
          n++;
          requestAnimationFrame(tick);
        };
        requestAnimationFrame(tick);
      }),
    ms,
  );
}

/**
 * Follows the link `hash` in the open page and waits until scene `id` has shown its final
 * picture and drawn it (a walk through the scenes in one page, as a reader following links).
 * @param {Page} page
 * @param {string} hash
 * @param {string} id
 */
export async function showScene(page, hash, id) {
  await page.evaluate((h) => (location.hash = h), hash);
  await page.waitForFunction(
    (want) => {
      const stage = /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'));
      return stage?.dataset.scene === want && stage.dataset.ready === '1';
    },
    id,
    { timeout: 60000 },
  );
  await ready(page, 60000);
  await framesAfter(page, 0);
}

/**
 * Waits until the viewer has drawn more than `after` frames.
 * @param {Page} page
 */
export async function framesAfter(page, after = 0) {
  await page.waitForFunction((n) => Number(document.body.dataset.frames ?? 0) > n, after, { timeout: 15000 });
  // one more animation frame so the compositor has the new picture
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return page.evaluate(() => Number(document.body.dataset.frames));
}

/**
 * A server (with extra response `headers`) and a browser for one test file, started before and
 * closed after its tests. `session.open(path)` opens a fresh page at `url + path` (or at `path`
 * when it is a whole URL), watching it
 * for problems and recording its requests, and waits for the first drawn frame unless
 * `wait: false`.
 */
export function pageSession({ headers = {} } = {}) {
  /**
   * @type {{url: string, browser: BrowserContext | null,
   *   open: (path?: string, options?: {wait?: boolean}) => Promise<{page: Page, problems: string[], requests: string[], frames: number}>}}
   */
  const session = {
    url: '',
    browser: null,
    open: async () => {
      throw new Error('the session has not started');
    },
  };
  /** @type {import('node:http').Server | undefined} */
  let server;
  before(async () => {
    ({ server, url: session.url } = await startServer({ headers }));
    session.browser = await launch();
  });
  after(async () => {
    await session.browser?.close();
    server?.close();
  });
  session.open = async (path = '', { wait = true } = {}) => {
    if (!session.browser) throw new Error('the session has not started');
    const page = await session.browser.newPage();
    const problems = watch(page);
    /** @type {string[]} */
    const requests = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(/^[a-z]+:/.test(path) ? path : session.url + path);
    if (wait) await ready(page);
    const frames = wait ? await framesAfter(page, 0) : 0;
    return { page, problems, requests, frames };
  };
  return session;
}
