// English and German: every scene in both languages, no English text of the English file in
// the German page (symbols and names aside), <html lang> following, decimal commas in German,
// and <ruled-view lang="de">.
import { test } from 'node:test';
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { pageSession, ready } from './browser.mjs';
import en from '../../www/i18n/en/index.js';
import de from '../../www/i18n/de/index.js';

const session = pageSession();

/** Plain-text fragments (≥ 12 characters) of every English text that German translates. */
function englishFragments() {
  const fragments = new Set();
  const german = Object.values(de).join('\n');
  for (const [key, text] of Object.entries(en)) {
    if (de[key] === text) continue;
    const plain = text
      .replace(/<math[\s\S]*?<\/math>/g, '\uE000')
      .replace(/<[^>]+>/g, ' ')
      .replace(/&lt;/g, '<')
      .replace(/&amp;/g, '&')
      .replace(/[_^]\{([^}]*)\}/g, '$1')
      .replace(/[_^](.)/g, '$1');
    for (const part of plain.split(/\{[^}]*\}|\uE000|[.;:()]/)) {
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
      for (const box of document.querySelectorAll('.rl-controls input[type=checkbox]'))
        if (!box.checked && !box.disabled) box.click();
    });
    await ready(page);
    await page.locator('.io summary').click();
    const shown = await page.evaluate(() => {
      const texts = [document.body.innerText, document.title];
      for (const el of document.querySelectorAll('[aria-label], [title], [placeholder]'))
        texts.push(el.getAttribute('aria-label') ?? '', el.getAttribute('title') ?? '');
      for (const o of document.querySelectorAll('option')) texts.push(o.textContent);
      texts.push(
        document.querySelector('.rl-shortcuts')?.textContent ?? '',
        document.querySelector('#share-dialog')?.textContent ?? '',
      );
      return texts.join('\n').replace(/\s+/g, ' ');
    });
    const english = fragments.filter((f) => shown.includes(f));
    assert.deepEqual(english, [], `${id}: English text on the German page`);
    if (id === 'striction')
      assert.match(await page.locator('.rl-readout').innerText(), /\d,\d{3}/, 'German numbers have decimal commas');
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
    await import('/www/index.js');
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

/** Fragments (≥ 12 characters) of the core's English messages (src/error/message.rs). */
function coreFragments() {
  const source = readFileSync(new URL('../../src/error/message.rs', import.meta.url), 'utf8');
  const body = source.slice(
    source.indexOf('pub const MESSAGES'),
    source.indexOf('];', source.indexOf('pub const MESSAGES')),
  );
  const templates = [...body.matchAll(/"((?:[^"\\]|\\.)*)"\s*,?\s*\)/g)].map(([, t]) => JSON.parse(`"${t}"`));
  return templates.flatMap((t) =>
    t
      .split(/\{\w+\}|[.;:()"]/)
      .map((f) => f.trim())
      .filter((f) => f.length >= 12 && /[a-z]{3}/.test(f)),
  );
}

test('every error path of the German page speaks German: formulas, imports, link values, the element, the start', async () => {
  const fragments = [...englishFragments(), ...coreFragments()];
  /** Visible text of `selector` (shadow roots included), outside elements marked lang="en". */
  const shown = (page, selector) =>
    page.evaluate((sel) => {
      const texts = [];
      const walk = (root) => {
        for (const e of root.querySelectorAll(sel)) if (!e.hidden && e.checkVisibility()) texts.push(e.cloneNode(true));
        for (const host of root.querySelectorAll('*')) if (host.shadowRoot) walk(host.shadowRoot);
      };
      walk(document);
      return texts
        .map((e) => {
          for (const x of e.querySelectorAll('[lang="en"]')) x.remove();
          return e.textContent;
        })
        .join(' | ');
    }, selector);
  const english = (text) => fragments.filter((f) => text.includes(f));
  const seen = [];
  // the page's sentences for a reason it has no text for: no path of the page may end there
  const generic = Object.entries(de)
    .filter(([k]) => k.startsWith('error.code.'))
    .map(([, v]) => v);
  const expectGerman = (what, text) => {
    assert.ok(text.trim().length > 0, `${what}: nothing shown`);
    assert.deepEqual(
      generic.filter((g) => text.includes(g)),
      [],
      `${what}: said only by its kind: ${text}`,
    );
    assert.deepEqual(english(text), [], `${what}: English on the German page: ${text}`);
    seen.push(text);
  };

  // formulas: every kind of mistake a student makes in a field, each shown beside it and over the view
  const { page, problems } = await session.open('#scene=formula&lang=de');
  const typed = [
    ['ez', ' '],
    ['ez', '3*'],
    ['ez', '2u'],
    ['ez', 'u u'],
    ['ez', 'sin u'],
    ['ez', 'u(2)'],
    ['ay', 'sni(u)'],
    ['ay', 'w*u'],
    ['ez', 'u (2)'],
    ['ez', ')'],
    ['ez', 'u*()'],
    ['ez', 'sin(u,)'],
    ['ez', 'atan2(u)'],
    ['ez', 'sin(u, 1)'],
    ['ez', '-----u'],
    ['ez', '**u'],
    ['ez', 'u^^2'],
    ['ez', '//u'],
    ['ax', 'u²'],
    ['ax', 'π*u'],
    ['ax', 'u × 2'],
    ['ax', 'u − 1'],
    ['ax', 'u ÷ 2'],
    ['ax', '[u]'],
    ['ax', 'u#'],
    ['ez', '(u'],
    ['ez', '2^u^2'],
    ['ez', 'atan2(1,5)'],
    ['ez', 'x'.repeat(1001)],
    ['ez', `${'('.repeat(70)}u${')'.repeat(70)}`],
    ['ex', 'sqrt(-1)'],
    ['ex', 'sqrt(u)'],
    ['umax', '-1'],
    ['umax', '1/0'],
    ['vmax', '-1'],
  ];
  const restore = { ez: 'c', ay: 'b*sin(u)', ax: 'a*cos(u)', ex: '-a*sin(u)', umax: '2*pi', umin: '0', vmax: '1' };
  for (const [key, value] of typed) {
    const field = page.locator(`.rl-controls [name="${key}"]`);
    await field.fill(value);
    await field.dispatchEvent('change');
    await page
      .waitForFunction(() => !document.querySelector('.rl-view .rl-error').hidden, null, { timeout: 10000 })
      .catch(() => assert.fail(`${key} = ${value}: no error shown`));
    expectGerman(`${key} = ${value.slice(0, 20)}`, await shown(page, '.rl-view .rl-error, .rl-fielderror'));
    await field.fill(restore[key]);
    await field.dispatchEvent('change');
    await page.waitForFunction(() => document.querySelector('.rl-view .rl-error').hidden, null, { timeout: 10000 });
  }
  // German decimal commas: in formulas and in number fields
  await page.locator('.rl-controls [name="ez"]').fill('0,5*c');
  await page.locator('.rl-controls [name="ez"]').dispatchEvent('change');
  await page.waitForTimeout(300);
  assert.equal(await page.locator('.rl-view .rl-error').isHidden(), true, '0,5 is refused in a German formula');
  const exact = page.locator('.rl-row[data-key="a"] .rl-exact');
  await exact.fill('0,5');
  await exact.dispatchEvent('change');
  await page.waitForFunction(() => window.ruledlab.stage.params.a === 0.5);
  // the convergence study of a cylinder: parallel rulings
  await page.evaluate(() => (location.hash = '#scene=formula&lang=de&ax=u&ay=0&az=0&ex=0&ey=0&ez=1&tool=convergence'));
  await page.waitForFunction(() => !document.querySelector('.rl-view .rl-error').hidden, null, { timeout: 10000 });
  expectGerman('convergence of a cylinder', await shown(page, '.rl-view .rl-error'));
  // a congruence whose direction vanishes, or is not finite
  for (const hash of [
    '#scene=formula&lang=de&ex=0&ey=0&ez=0',
    '#scene=formula-congruence&lang=de&ex=0&ey=0&ez=0',
    '#scene=formula-congruence&lang=de&ex=1/(u-u)',
  ]) {
    await page.evaluate((h) => (location.hash = h), hash);
    await page.waitForFunction(() => !document.querySelector('.rl-view .rl-error').hidden, null, { timeout: 10000 });
    expectGerman(hash, await shown(page, '.rl-view .rl-error'));
  }

  // imports: pasted CSV and JSON a student gets wrong
  await page.evaluate(() => (location.hash = '#scene=striction&lang=de'));
  await page.waitForFunction(() => document.querySelector('.rl-stage')?.dataset.scene === 'striction');
  await page.locator('.io summary').click();
  const imports = [
    'a,b\nx,1,2,3,4,5',
    '0,0,0,1,0\n',
    '0,0,0,1,0,0\n0,0,1,0,x,1',
    '0,0,0,1,0,1e999',
    '# nothing\n',
    '{"segments": [[0,0,0,1,0,0]',
    '[1, 2',
    '{"a" 1}',
    '{1: 2}',
    '{"segments": [], "rows": 2',
    '"abc',
    'true false',
    '[nul]',
    '[1] 2',
    '{"rows": 2}',
    '{"segments": [[0,0,0,1,0,0]], "rows": 1, "cols": 2}',
    '{"segments": [[0,0,0,1,0,0]], "rows": 2}',
    '{"segments": 5}',
    '{"segments": [[0,0,0,1,0]]}',
    '{"segments": [["x"]]}',
    '{"segments": [7]}',
    '[0,0,0,1,0,0,1]',
    '{"segments": [[0,0,0,1,0,0],[0,0,1,0,1,1]], "rows": 2, "cols": 2}',
    '['.repeat(20) + ']'.repeat(20),
    // files that read but cannot be computed with: one ruling, a zero-length one, a grid line of zero length
    '0,0,0,1,0,0\n',
    '0,0,0,0,0,0\n1,1,1,2,2,2\n',
    '{"segments": [[0,0,0,0,0,0],[1,0,0,1,0,1],[0,1,0,0,1,1],[1,1,0,1,1,1]], "rows": 2, "cols": 2}',
    // a German spreadsheet's line with too few numbers
    'ax;ay;az;bx;by;bz\n1,5;0;0;0;1\n',
  ];
  for (const text of imports) {
    await page.locator('#import-text').fill(text);
    await page.locator('#import-button').click();
    await page
      .waitForFunction(() => !document.getElementById('import-error').hidden, null, { timeout: 5000 })
      .catch(() => assert.fail(`import ${JSON.stringify(text)}: no error`));
    expectGerman(`import ${JSON.stringify(text)}`, await shown(page, '#import-error'));
  }
  // link values the page cannot use
  for (const hash of [
    '#lang=de&scene=striction&n=abc',
    '#lang=de&scene=striction&n=9999',
    '#lang=de&scene=striction&surface=nope',
    '#lang=de&scene=striction&strip=maybe',
    '#lang=de&scene=nope',
    '#lang=de&scene=striction&cam=1,2',
    '#lang=de&scene=data&data=1,2,3',
    '#lang=de&paper=fig99',
    `#lang=de&scene=formula&ax=${'u'.repeat(1200)}`,
    `#lang=de&${'x'.repeat(70000)}`,
  ]) {
    await page.evaluate((h) => (location.hash = h), hash);
    await page
      .waitForFunction(() => !document.querySelector('.rl-note').hidden, null, { timeout: 10000 })
      .catch(() => assert.fail(`${hash.slice(0, 40)}: no note`));
    expectGerman(hash.slice(0, 40), await shown(page, '.rl-note'));
  }
  // the element's errors
  await page.evaluate(async () => {
    await import('/www/index.js');
    for (const [k, v] of [
      ['scene', 'nope'],
      ['paper', 'fig99'],
      ['camera', 'x'],
    ]) {
      const e = document.createElement('ruled-view');
      if (k === 'camera') e.setAttribute('scene', 'curves');
      e.setAttribute(k, v);
      e.setAttribute('lang', 'de');
      e.className = 'failing';
      document.body.append(e);
    }
  });
  await page.waitForFunction(
    () =>
      [...document.querySelectorAll('ruled-view.failing')].every((v) =>
        v.shadowRoot.querySelector('.rl-error:not([hidden]), .rl-note:not([hidden])'),
      ),
    null,
    { timeout: 10000 },
  );
  expectGerman(
    'element',
    await page.evaluate(() =>
      [...document.querySelectorAll('ruled-view.failing')]
        .map((v) =>
          [...v.shadowRoot.querySelectorAll('.rl-error:not([hidden]), .rl-note:not([hidden])')]
            .map((e) => e.textContent)
            .join(' '),
        )
        .join(' | '),
    ),
  );
  assert.deepEqual(problems, []);
  await page.close();

  // the start: the wasm does not load
  const start = await session.browser.newPage();
  await start.route('**/ruledlab_bg.wasm', (route) => route.fulfill({ status: 404, body: 'gone' }));
  await start.goto(`${session.url}#lang=de`);
  await start.waitForFunction(
    () => /konnte nicht starten/.test(document.getElementById('boot')?.textContent ?? ''),
    null,
    { timeout: 20000 },
  );
  expectGerman('start', await shown(start, '#boot'));
  await start.close();
  console.log(`# ${seen.length} German error messages checked`);
  if (process.env.SHOW_MESSAGES) console.log(seen.join('\n'));
});
