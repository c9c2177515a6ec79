// The page in headless Chromium: loads cleanly, draws, its controls change the picture, every
// scene and every choice of each of its menus works, links restore every control, history
// follows scene changes, and the tools around the view (reset, play, share) do their job.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, shoot, framesAfter, ready, control, setControl, launch, showScene } from './browser.mjs';
import { countDifferent, countChanged } from './png.mjs';

const BACKGROUND = [251, 250, 247];
const session = pageSession();
const open = (hash = '') => session.open(hash);

test('the page loads without errors or failed requests, favicon included, and draws', async () => {
  const { page, problems } = await open();
  const image = await shoot(page, 'striction-hyperboloid');
  const drawn = countDifferent(image, BACKGROUND);
  assert.ok(drawn > 0.05 * image.width * image.height, `only ${drawn} pixels differ from the background`);
  assert.match(await page.title(), /ruledlab/);
  assert.match(page.url(), /#scene=striction&surface=hyperboloid&n=36&.*cam=/);
  assert.match(await page.locator('.rl-readout').innerText(), /max \|mi − s\(ui\)\|/);
  assert.match(await page.locator('.rl-caption').innerText(), /Hyperboloid.*36 rulings/);
  assert.equal(await page.locator('#boot').count(), 0, 'the loading message is gone');
  assert.deepEqual(problems, []);
  await page.close();
});

test('dragging orbits the camera and changes the picture', async () => {
  const { page, problems, frames } = await open();
  const before = await shoot(page, 'drag-before');
  const box = await page.locator('.rl-view canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 150, box.y + box.height / 2 + 40, { steps: 5 });
  await page.mouse.up();
  await framesAfter(page, frames);
  const afterDrag = await shoot(page, 'drag-after');
  assert.ok(countChanged(before, afterDrag) > 2000, 'the picture did not change');
  assert.deepEqual(problems, []);
  await page.close();
});

test('every scene, and every choice of each of its menus, draws without errors', async () => {
  // one page, the scenes opened by their links in turn (each at its defaults)
  const { page, problems } = await open();
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  assert.ok(scenes.length >= 13);
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    const start = await shoot(page, `${id}-default`);
    assert.ok(countDifferent(start, BACKGROUND) > 0.005 * start.width * start.height, `${id} drew nothing`);
    // its first enabled slider changes the picture
    const slider = await page.evaluate(() => {
      const r = [...document.querySelectorAll('.rl-controls input[type=range]')].find((x) => !x.disabled);
      return r ? { key: r.name, value: Number(r.value) === Number(r.min) ? r.max : r.min } : null;
    });
    if (slider) {
      await setControl(page, slider.key, slider.value);
      const moved = await shoot(page, `${id}-slider`);
      assert.ok(countChanged(start, moved) > 300, `${id}: moving ${slider.key} did not change the picture`);
    }
    // every choice of every menu draws
    const menus = await page.evaluate(() =>
      [...document.querySelectorAll('.rl-controls select')].map((s) => ({
        key: s.name,
        values: [...s.options].map((o) => o.value),
      })),
    );
    for (const { key, values } of menus) {
      for (const value of [...values.slice(1), values[0]]) {
        if ((await control(page, key).inputValue()) === value || (await control(page, key).isDisabled())) continue;
        const frames = await page.evaluate(() => Number(document.body.dataset.frames));
        await control(page, key).selectOption(value);
        await framesAfter(page, frames).catch(async () =>
          assert.fail(
            `${id}: ${key}=${value} drew no new frame; error: ${await page.locator('.rl-error').innerText()}`,
          ),
        );
        await ready(page, 60000);
        assert.equal(
          await page.locator('.rl-error').isHidden(),
          true,
          `${id}: ${key}=${value} shows an error: ${await page.locator('.rl-error').innerText()}`,
        );
      }
    }
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('a link restores every control of every scene, the camera and the language', async () => {
  // each scene's controls read in one page walking the scenes by their links; each link then
  // opened in a fresh page, as a reader opens it
  const { page, problems } = await open();
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    // a non-default value for every enabled control (sliders away from their default,
    // checkboxes flipped, menus at another choice)
    const changed = await page.evaluate(() => {
      const out = {};
      for (const el of document.querySelectorAll('.rl-controls [name]')) {
        if (el.disabled || el.type === 'text') continue;
        if (el.type === 'range') {
          const [min, max, step] = [Number(el.min), Number(el.max), Number(el.step)];
          const v = Number(el.value) === max ? min : Math.min(max, Number(el.value) + step);
          out[el.name] = String(Number(v.toFixed(6)));
        } else if (el.type === 'checkbox') out[el.name] = el.checked ? '0' : '1';
        else if (el.tagName === 'SELECT' && el.name !== 'preset')
          out[el.name] = [...el.options].map((o) => o.value).find((v) => v !== el.value);
      }
      return out;
    });
    const hash = new URLSearchParams({ scene: id, ...changed, cam: '0.5,0.3,7,0.1,0.2,0.3', lang: 'en' });
    const restored = await open(`#${hash}`);
    const values = await restored.page.evaluate(
      (keys) =>
        Object.fromEntries(
          keys.map((k) => {
            const el = document.querySelector(`.rl-controls [name="${k}"]`);
            return [k, el.type === 'checkbox' ? (el.checked ? '1' : '0') : String(el.value)];
          }),
        ),
      Object.keys(changed),
    );
    for (const [k, v] of Object.entries(changed))
      assert.equal(
        Number.isNaN(Number(v)) ? values[k] : Number(values[k]),
        Number.isNaN(Number(v)) ? v : Number(v),
        `${id}: ${k} was not restored`,
      );
    const camera = await restored.page.evaluate(() => window.ruledlab.stage.viewer.camera.toArray());
    assert.deepEqual(
      camera.map((x) => Number(x.toFixed(6))),
      [0.5, 0.3, 7, 0.1, 0.2, 0.3],
      `${id}: the camera was not restored`,
    );
    // and the page writes back the same state
    const written = new URLSearchParams(new URL(restored.page.url()).hash.slice(1));
    for (const [k, v] of Object.entries(changed))
      assert.equal(
        Number.isNaN(Number(v)) ? written.get(k) : Number(written.get(k)),
        Number.isNaN(Number(v)) ? v : Number(v),
        `${id}: ${k} not in the written link`,
      );
    assert.deepEqual([...problems, ...restored.problems], []);
    await restored.page.close();
  }
  await page.close();
});

test('the scene’s own parameter "view" and the camera no longer collide (isometry, three panels)', async () => {
  const { page, problems } = await open('#scene=isometry&layout=panels&cam=1,0.5,9,0,0,0');
  assert.equal(await control(page, 'layout').inputValue(), 'panels');
  assert.equal(await control(page, 't').isDisabled(), true, 'bending t does nothing in the three-panel view');
  assert.match(await page.locator('.rl-row[data-key="t"] .rl-reason').innerText(), /three-panel view/);
  await page.reload();
  await ready(page);
  assert.equal(await control(page, 'layout').inputValue(), 'panels');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a scene change is a history entry; parameter moves are not; Back returns to the previous scene', async () => {
  const { page, problems } = await open('#scene=striction');
  const length = await page.evaluate(() => history.length);
  await setControl(page, 'n', 20);
  assert.equal(await page.evaluate(() => history.length), length, 'a parameter move added a history entry');
  await page.locator('#scene').selectOption('curves');
  await ready(page);
  assert.equal(await page.evaluate(() => history.length), length + 1);
  await page.goBack();
  await page.waitForFunction(() => window.ruledlab.stage.scene?.id === 'striction');
  await ready(page);
  assert.equal(await control(page, 'n').inputValue(), '20', 'Back restores the previous scene with its parameters');
  assert.deepEqual(problems, []);
  await page.close();
});

test('Reset restores the defaults; bad link values fall back to their defaults with a visible note', async () => {
  const { page, problems } = await open('#scene=striction&n=oops&surface=torus&normals=maybe&polygon=0');
  assert.equal(await control(page, 'n').inputValue(), '36');
  assert.equal(await control(page, 'surface').inputValue(), 'hyperboloid');
  const note = await page.locator('.rl-note').innerText();
  assert.match(note, /“n” is not a number/);
  assert.match(note, /“surface” is not one of the choices/);
  assert.equal(await control(page, 'polygon').isChecked(), false);
  await page.locator('.rl-reset').click();
  await ready(page);
  assert.equal(await control(page, 'polygon').isChecked(), true);
  assert.deepEqual(problems, []);
  await page.close();
});

test('play moves a parameter until paused; a single step moves it once', async () => {
  const { page, problems } = await open('#scene=isometry&t=0');
  await page.locator('.rl-row[data-key="t"] .rl-play').click();
  await page.waitForFunction(() => Number(document.querySelector('.rl-controls [name="t"]').value) > 0.1, null, {
    timeout: 10000,
  });
  assert.equal(await page.locator('.rl-row[data-key="t"] .rl-play').getAttribute('aria-pressed'), 'true');
  await page.locator('.rl-row[data-key="t"] .rl-play').click();
  const paused = await page.evaluate(() => window.ruledlab.stage.params.t);
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.ruledlab.stage.params.t), paused, 'pause stops the parameter');
  assert.match(page.url(), new RegExp(`t=${paused}&`));
  await page.locator('.rl-player button').click();
  assert.ok(
    Math.abs((await page.evaluate(() => window.ruledlab.stage.params.t)) - paused) > 0.04,
    'a single step moves t by a twentieth of its range',
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('autoplay plays, unless the reader prefers reduced motion', async () => {
  const moving = await open('#scene=lines&slide=0&autoplay');
  await moving.page.waitForFunction(
    () => Number(document.querySelector('.rl-controls [name="slide"]').value) > 0.05,
    null,
    { timeout: 10000 },
  );
  await moving.page.close();
  const context = session.browser;
  const page = await context.newPage();
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.goto(`${session.url}#scene=lines&slide=0&autoplay`);
  await ready(page);
  await page.waitForTimeout(600);
  assert.equal(Number(await control(page, 'slide').inputValue()), 0, 'autoplay ignored the reduced-motion preference');
  await page.close();
});

test('the share dialog offers the link, an iframe and a <ruled-view> snippet of this view', async () => {
  const { page, problems } = await open('#scene=curves&w=0.0625&steps=3');
  await page.locator('#share').click();
  const link = await page.locator('#share-link').inputValue();
  assert.match(link, /#scene=curves&.*w=0\.0625.*&cam=/);
  const iframe = await page.locator('#share-iframe').inputValue();
  // the control points are handles: readers of the iframe may drag them (#embed&edit)
  assert.match(iframe, /^<iframe src="[^"]*#embed&amp;controls&amp;edit&amp;scene=curves/);
  const element = await page.locator('#share-element').inputValue();
  assert.match(
    element,
    /<ruled-view scene="curves" params="[^"]*w=0\.0625[^"]*" camera="[-\d.,e]+" lang="en" controls editable/,
  );
  assert.match(element, /<script defer src="http[^"]*\/dist\/ruledlab-embed\.js"><\/script>/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('your surface by formulas: live, in the link, and errors beside the field with their column', async () => {
  const { page, problems } = await open('#scene=formula');
  const before = await shoot(page, 'formula-before');
  await setControl(page, 'ez', '2*c');
  const after = await shoot(page, 'formula-after');
  assert.ok(countChanged(before, after) > 1000, 'a new formula did not change the picture');
  await page.waitForFunction(() => /ez=2\*c|ez=2%2Ac/.test(location.hash));
  await control(page, 'ay').fill('sni(u)');
  await control(page, 'ay').dispatchEvent('change');
  const row = page.locator('.rl-row[data-key="ay"]');
  await page.waitForFunction(() => document.querySelector('.rl-row[data-key="ay"] .rl-fielderror')?.hidden === false);
  assert.match(
    await row.locator('.rl-fielderror').innerText(),
    /^The y component of a\(u\): there is no function “sni” \(column 1\); known: sin, cos/,
  );
  assert.equal(await control(page, 'ay').getAttribute('aria-invalid'), 'true');
  // the link with the formula restores it
  const reloaded = await open(`#scene=formula&ez=${encodeURIComponent('2*c')}&tool=convergence`);
  assert.equal(await control(reloaded.page, 'ez').inputValue(), '2*c');
  assert.match(await reloaded.page.locator('.rl-readout').innerText(), /order of the midpoint/);
  assert.deepEqual(
    [...problems, ...reloaded.problems].filter((p) => !/sni/.test(p)),
    [],
  );
  await page.close();
  await reloaded.page.close();
});

test('imports: errors beside the field, old data kept; small imports survive a reload in the link', async () => {
  const { page, problems } = await open('#scene=data');
  await page.locator('.io summary').click();
  await page.locator('#import-text').fill('0,0,0,1,0,0\n0,0,1,0,1,x');
  await page.locator('#import-button').click();
  assert.match(
    await page.locator('#import-error').innerText(),
    /^CSV: “x” is not a number \(line 2, column 11\)\. The example data stays on screen/,
  );
  await page.locator('#import-text').fill('0,0,0,1,0,0\n0,0,1,0,1,1\n0,0,2,-1,0,2\n0,0,3,0,-1,3');
  await page.locator('#import-button').click();
  await page.waitForFunction(() => /data=/.test(location.hash));
  assert.equal(await page.locator('#import-error').isHidden(), true);
  await page.reload();
  await ready(page);
  assert.match(await page.locator('.rl-readout').innerText(), /rulings N\s+4/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('phone size: the panel goes below the view, Fit frames the width, touch targets are large enough', async () => {
  const phone = await launch({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  const page = await phone.newPage();
  await page.goto(`${session.url}#scene=striction`);
  await ready(page);
  assert.equal(await page.locator('.rl-stage').evaluate((e) => e.classList.contains('rl-narrow')), true);
  const small = await page.evaluate(() =>
    [...document.querySelectorAll('.rl-stage button, .rl-stage input, .rl-stage select')]
      .filter((e) => e.offsetParent)
      .map((e) => ({ what: e.name || e.className || e.textContent, ...e.getBoundingClientRect().toJSON() }))
      .filter((r) => r.width < 24 || r.height < 24),
  );
  assert.deepEqual(small, [], 'controls smaller than 24 × 24 CSS px');
  assert.match(await page.locator('.rl-hint').textContent(), /finger/, 'the hint speaks of touch, not of the mouse');
  // Fit frames the width too: the surface's extent across stays inside the view
  const image = await shoot(page, 'phone-striction');
  let left = image.width,
    right = 0;
  for (let y = 2; y < image.height - 2; y++) {
    for (let x = 0; x < image.width; x++) {
      const k = (y * image.width + x) * image.channels;
      if (Math.abs(image.data[k] - 251) + Math.abs(image.data[k + 1] - 250) + Math.abs(image.data[k + 2] - 247) > 30) {
        left = Math.min(left, x);
        right = Math.max(right, x);
      }
    }
  }
  assert.ok(
    left > 2 && right < image.width - 3,
    `the surface is cut at the sides: drawn from x = ${left} to ${right} of ${image.width}`,
  );
  await phone.close();
});
