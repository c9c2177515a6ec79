// The package through Vite: a tiny app imports 'ruledlab' by name (resolved through the
// package's `exports`), Vite builds it, and the built app runs in Chromium.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, readdirSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { startServer } from '../../scripts/serve.mjs';
import { launch, watch } from './browser.mjs';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
let browser;
before(async () => (browser = await launch()));
after(async () => browser?.close());

test('a Vite app built with the package computes in the browser', async () => {
  const app = mkdtempSync(join(tmpdir(), 'ruledlab-vite-'));
  mkdirSync(join(app, 'node_modules'));
  symlinkSync(REPO, join(app, 'node_modules', 'ruledlab'), 'dir');
  writeFileSync(join(app, 'index.html'), '<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>vite app</title></head><body><script type="module" src="./main.js"></script></body></html>');
  writeFileSync(
    join(app, 'main.js'),
    `import init, { AnalyticSurface } from 'ruledlab';
await init();
const helicoid = AnalyticSurface.byName('helicoid');
document.body.dataset.delta = String(helicoid.sample(40).invariants().distribution[0]);
`,
  );
  await build({ root: app, logLevel: 'silent', build: { outDir: join(app, 'dist'), target: 'es2022' } });
  const assets = readdirSync(join(app, 'dist', 'assets'));
  assert.ok(assets.some((f) => f.endsWith('.wasm')), `no wasm in ${assets}`);
  const { server, url } = await startServer({ root: join(app, 'dist') });
  try {
    const page = await browser.newPage();
    const problems = watch(page);
    await page.goto(url);
    await page.waitForFunction(() => document.body.dataset.delta !== undefined, null, { timeout: 20000 });
    assert.ok(Math.abs(Number(await page.evaluate(() => document.body.dataset.delta)) - 0.5) < 1e-12);
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    server.close();
  }
});
