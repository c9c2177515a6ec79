// The page in a second engine: Debian's Firefox ESR driven by geckodriver through
// selenium-webdriver (WebDriver BiDi for the console). Headless Firefox has no WebGL2 on these
// machines, so scripts/test.sh runs this headed under Xvfb (xvfb-run) with Mesa's software
// renderer. Every scene must draw (pixels differ from the background), with no console error,
// no uncaught exception and no failed request.
// Usage: xvfb-run -a node tests/firefox/smoke.mjs
import { Builder, By, until } from 'selenium-webdriver';
import firefox from 'selenium-webdriver/firefox.js';
import LogInspector from 'selenium-webdriver/bidi/logInspector.js';
import { startServer } from '../../scripts/serve.mjs';
import { decodePng, countDifferent } from '../page/png.mjs';

const { server, url } = await startServer();
const options = new firefox.Options().enableBidi().windowSize({ width: 1100, height: 800 });
options.setBinary(process.env.FIREFOX ?? '/usr/bin/firefox-esr');
options.setPreference('webgl.force-enabled', true);
const service = new firefox.ServiceBuilder(process.env.GECKODRIVER ?? 'geckodriver');
const driver = await new Builder().forBrowser('firefox').setFirefoxOptions(options).setFirefoxService(service).build();

/** @type {string[]} */
const problems = [];
let failed = 0;
try {
  const inspector = await LogInspector(driver);
  await inspector.onConsoleEntry((/** @type {any} */ entry) => {
    if (entry.level === 'error') problems.push(`console error: ${entry.text}`);
  });
  await inspector.onJavascriptException((/** @type {any} */ entry) => problems.push(`exception: ${entry.text}`));

  await driver.get(url);
  await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
  const webgl2 = await driver.executeScript('return !!document.createElement("canvas").getContext("webgl2")');
  if (!webgl2) throw new Error('Firefox has no WebGL2 here: run under xvfb-run (headed), not headless');
  const scenes = /** @type {string[]} */ (await driver.executeScript('return window.ruledlab.scenes.map((s) => s.id)'));
  const background = /** @type {number[]} */ (
    await driver.executeScript(
      'const c = getComputedStyle(document.querySelector(".rl-view")).getPropertyValue("--rl-bg") || getComputedStyle(document.body).backgroundColor; return c.match(/\\d+/g).slice(0, 3).map(Number)',
    )
  );
  for (const scene of scenes) {
    const before = problems.length;
    await driver.get(`${url}#scene=${scene}`);
    await driver.navigate().refresh();
    await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
    await driver.sleep(300);
    const canvas = await driver.findElement(By.css('.rl-view canvas'));
    const image = decodePng(Buffer.from(await canvas.takeScreenshot(), 'base64'));
    const drawn = countDifferent(image, background, 24) / (image.width * image.height);
    const failedRequests = /** @type {string[]} */ (
      await driver.executeScript(
        "return performance.getEntriesByType('resource').filter((e) => e.responseStatus >= 400).map((e) => e.name)",
      )
    );
    failedRequests.forEach((r) => problems.push(`failed request: ${r}`));
    const ok = drawn > 0.005 && problems.length === before;
    if (!ok) failed++;
    console.log(`${ok ? 'ok' : 'not ok'} - Firefox: ${scene} draws (${(100 * drawn).toFixed(1)} % of the view)${problems.slice(before).map((p) => `\n  ${p}`).join('')}`);
  }
} finally {
  await driver.quit();
  server.close();
}
if (failed || problems.length) {
  console.error(`Firefox smoke test: ${failed} scene(s) failed; ${problems.length} problem(s)`);
  process.exit(1);
}
console.log('Firefox smoke test: every scene draws, no console error, no failed request');
