// English and German: every scene in both languages, no English text of the English file in
// the German page (symbols and names aside), <html lang> following, decimal commas in German,
// and <ruled-view lang="de">.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, ready } from './browser.mjs';
import en from '../../www/i18n/en.js';
import de from '../../www/i18n/de.js';

const session = pageSession();

/** Plain-text fragments (≥ 12 characters) of every English text that German translates. */
function englishFragments() {
  const fragments = new Set();
  const german = Object.values(de).join('\n');
  for (const [key, text] of Object.entries(en)) {
    if (de[key] === text) continue;
    const plain = text
      .replace(/<math[\s\S]*?<\/math>/g, '\u0000')
      .replace(/<[^>]+>/g, ' ')
      .replace(/&lt;/g, '<')
      .replace(/&amp;/g, '&')
      .replace(/[_^]\{([^}]*)\}/g, '$1')
      .replace(/[_^](.)/g, '$1');
    for (const part of plain.split(/\{[^}]*\}|\u0000|[.;:()]/)) {
      const f = part.replace(/\s+/g, ' ').trim();
      if (f.length >= 12 && /[a-z]{3}/.test(f) && !german.includes(f)) fragments.add(f);
    }
  }
  return [...fragments];
}

test('German: every scene, every visible text German, numbers with decimal commas', async () => {
  const fragments = englishFragments();
  assert.ok(fragments.length > 200, `only ${fragments.length} fragments to look for`);
  const first = await session.open('#lang=de');
  const scenes = await first.page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  assert.equal(await first.page.evaluate(() => document.documentElement.lang), 'de');
  await first.page.close();
  for (const id of scenes) {
    const { page, problems } = await session.open(`#scene=${id}&lang=de`);
    // every legend entry and control visible: turn on every checkbox
    await page.evaluate(() => {
      for (const box of document.querySelectorAll('.rl-controls input[type=checkbox]')) if (!box.checked && !box.disabled) box.click();
    });
    await ready(page);
    await page.locator('.io summary').click();
    const shown = await page.evaluate(() => {
      const texts = [document.body.innerText, document.title];
      for (const el of document.querySelectorAll('[aria-label], [title], [placeholder]')) texts.push(el.getAttribute('aria-label') ?? '', el.getAttribute('title') ?? '');
      for (const o of document.querySelectorAll('option')) texts.push(o.textContent);
      texts.push(document.querySelector('.rl-shortcuts')?.textContent ?? '', document.querySelector('#share-dialog')?.textContent ?? '');
      return texts.join('\n').replace(/\s+/g, ' ');
    });
    const english = fragments.filter((f) => shown.includes(f));
    assert.deepEqual(english, [], `${id}: English text on the German page`);
    if (id === 'striction') assert.match(await page.locator('.rl-readout').innerText(), /\d,\d{3}/, 'German numbers have decimal commas');
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('the language switch changes the page and the link; <ruled-view lang="de"> speaks German', async () => {
  const { page, problems } = await session.open('#scene=strip');
  assert.match(await page.locator('.rl-panel h2').first().innerText(), /Variational strip subdivision/);
  await page.locator('#lang').selectOption('de');
  await page.waitForFunction(() => document.documentElement.lang === 'de');
  assert.match(await page.locator('.rl-panel h2').first().innerText(), /Variationelle Streifenunterteilung/);
  assert.match(page.url(), /lang=de/);
  await page.evaluate(async () => {
    await import('/www/view.js');
    const v = document.createElement('ruled-view');
    v.setAttribute('scene', 'isometry');
    v.setAttribute('lang', 'de');
    v.setAttribute('controls', '');
    v.id = 'german';
    document.body.append(v);
  });
  await page.waitForFunction(() => document.getElementById('german').dataset.ready === '1');
  const labels = await page.locator('#german').evaluate((v) => v.shadowRoot.querySelector('.rl-controls').innerText);
  assert.match(labels, /Verbiegung t/);
  assert.doesNotMatch(labels, /Bending/);
  assert.deepEqual(problems, []);
  await page.close();
});
