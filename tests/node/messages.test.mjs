// The core's messages in every language of the page: each reason of the core's catalogues
// (src/error/message.rs, crates/ruledlab-cam/src/messages.rs) has a text in en/errors.js and de/errors.js using only values the core
// gives; errors through the package carry their reason and values (numbers as numbers); the
// page's sentence is built from them in the reader's language, German decimal commas
// included; and German formulas take decimal commas.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import ruledlab from './load.mjs';
import en from '../../www/i18n/en/index.js';
import de from '../../www/i18n/de/index.js';
import { translator } from '../../www/i18n/index.js';
import { describeError } from '../../www/ui/errors.js';

const { AnalyticSurface, importSegments, RuledSurface } = ruledlab;
const LANGUAGES = { en, de };

/** The catalogues as the Rust sources write them — the geometry's and the CAM crate's: [reason, template] pairs. */
function catalogue() {
  return [
    ...pairsOf('../../src/error/message.rs', 'pub const MESSAGES'),
    ...pairsOf('../../crates/ruledlab-cam/src/messages.rs', 'pub const CAM_MESSAGES'),
  ];
}

/** The [reason, template] pairs of the catalogue `start` opens in a Rust source. */
function pairsOf(/** @type {string} */ file, /** @type {string} */ start) {
  const source = readFileSync(new URL(file, import.meta.url), 'utf8');
  const body = source.slice(source.indexOf(start), source.indexOf('];', source.indexOf(start)));
  const pairs = [...body.matchAll(/\(\s*(TEXT_REASON|"[a-z0-9-]+")\s*,\s*"((?:[^"\\]|\\.)*)"\s*,?\s*\)/g)].map(
    ([, r, t]) => [r === 'TEXT_REASON' ? 'text' : JSON.parse(r), JSON.parse(`"${t}"`)],
  );
  return pairs;
}

/** Placeholders of a template: {name}, and {name:one:many}. */
const placeholders = (text) => new Set([...text.matchAll(/\{(\w+)(?::[^}]*)?\}/g)].map((m) => m[1]));

test('every reason of the core has a text in every language, with values the core gives', () => {
  const reasons = catalogue();
  assert.ok(reasons.length > 80, `only ${reasons.length} reasons read from src/error/message.rs`);
  for (const [reason, template] of reasons) {
    const given = placeholders(template);
    // a value named "…Reason" stands for a hint text, put in place of the name without the suffix
    for (const name of [...given]) if (name.endsWith('Reason')) given.add(name.slice(0, -6));
    if (reason === 'unexpected-character') given.add('hint');
    for (const [lang, table] of Object.entries(LANGUAGES)) {
      const text = table[`error.${reason}`];
      assert.ok(text, `${lang}: no text for reason "${reason}"`);
      for (const name of placeholders(text))
        assert.ok(
          given.has(name),
          `${lang}: "${reason}" uses {${name}}, which the core does not give (it gives ${[...given].join(', ') || 'nothing'})`,
        );
    }
    assert.deepEqual(
      placeholders(en[`error.${reason}`]),
      placeholders(de[`error.${reason}`]),
      `"${reason}": English and German use different values`,
    );
  }
  // and no text for a reason the core does not have
  const known = new Set(reasons.map(([r]) => `error.${r}`));
  const page = /^error\.(field|seeField|at\w+|hintJoin|code\.|what\.|option\.)/;
  for (const [lang, table] of Object.entries(LANGUAGES)) {
    for (const key of Object.keys(table))
      if (key.startsWith('error.') && !page.test(key))
        assert.ok(known.has(key), `${lang}: ${key} is no reason of the core`);
  }
});

test('an error through the package carries its reason and values; the page says it in German', () => {
  const de = translator('de');
  const en = translator('en');
  const cases = [
    [
      () => AnalyticSurface.fromFormulas({ a: ['u', '0', '0'], e: ['0', '1', '3*'], u: [0, 1] }),
      'ends-expecting-operand',
      {},
      'e[2]: Die Formel endet, wo ein Operand erwartet wird (Spalte 3).',
    ],
    [
      () => AnalyticSurface.fromFormulas({ a: ['u', 'sni(u)', '0'], e: ['0', '1', 'u'], u: [0, 1] }),
      'unknown-function',
      { name: 'sni' },
      'a[1]: Eine Funktion „sni“ gibt es nicht (Spalte 1); bekannt sind:',
    ],
    [
      () => AnalyticSurface.fromFormulas({ a: ['u', '0', '0'], e: ['0', '1', 'u'], u: [2.5, 1] }),
      'interval-order',
      { lo: 2.5, hi: 1 },
      'Bereich von u: Der Anfang muss kleiner als das Ende sein; angegeben ist [2,5; 1].',
    ],
    [
      () => importSegments('0,0,0,1,0\n'),
      'csv-six-numbers',
      { found: 5 },
      'CSV: Eine Zeile braucht 6 Zahlen (a.x a.y a.z b.x b.y b.z), diese hat 5 (Zeile 1, Spalte 10).',
    ],
    [
      () => RuledSurface.fromSegments(new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, NaN, 1])),
      'not-finite-segment',
      { item: 1, coordinate: 'b.y' },
      'Koordinate b.y der Erzeugenden 1 ist NaN; jede Koordinate muss eine endliche Zahl sein.',
    ],
  ];
  for (const [call, reason, values, german] of cases) {
    let error;
    try {
      call();
    } catch (e) {
      error = e;
    }
    assert.ok(error instanceof Error, `${reason}: no error`);
    assert.equal(error.details.reason, reason, error.message);
    for (const [k, v] of Object.entries(values)) assert.deepEqual(error.details.args[k], v, `${reason}.${k}`);
    const said = describeError(error, de, error.details.option === 'u' ? de.t('error.option.u') : undefined);
    assert.ok(said.startsWith(german), `${reason}: ${said}`);
    // the English page says it too, and the API's message stays the core's English
    assert.doesNotMatch(describeError(error, en), /\{\w+\}/);
  }
});

test('German formulas take decimal commas; atan2(1,5) is refused with the two ways to write it', () => {
  const s = AnalyticSurface.fromFormulas({
    a: ['0,5*u', '0', '0'],
    e: ['0', '1', 'u'],
    u: ['0', '1,5'],
    decimalComma: true,
  });
  try {
    assert.deepEqual([...s.parameters(2, { closed: false })], [0, 1.5]);
    const x = s.sample(2).segments();
    assert.equal(x[6], 0.75, 'a(1.5) = 0.5 · 1.5');
  } finally {
    s.free();
  }
  assert.throws(
    () => AnalyticSurface.fromFormulas({ a: ['0,5*u', '0', '0'], e: ['0', '1', 'u'], u: [0, 1] }),
    (e) => e.details.reason === 'comma-outside-atan2',
  );
  // an English reader of a German link: 0,5 is still a number, atan2(1,5) has two arguments
  const english = AnalyticSurface.fromFormulas({
    a: ['0,5*u', 'atan2(1,5)', '0'],
    e: ['0', '1', 'u'],
    u: ['0', '1,5'],
    decimalComma: 'unambiguous',
  });
  try {
    const x = english.sample(2).segments();
    assert.equal(x[6], 0.75);
    assert.equal(x[1], Math.atan2(1, 5) - 1, 'a.y − e.y at v = −1');
  } finally {
    english.free();
  }
  assert.throws(
    () =>
      AnalyticSurface.fromFormulas({ a: ['u', '0', '0'], e: ['0', '1', 'u'], u: [0, 1], decimalComma: 'sometimes' }),
    (e) => e.code === 'invalid-argument',
  );
  try {
    AnalyticSurface.fromFormulas({ a: ['atan2(1,5)', '0', '0'], e: ['0', '1', 'u'], u: [0, 1], decimalComma: true });
    assert.fail('accepted');
  } catch (e) {
    assert.equal(e.details.reason, 'ambiguous-comma');
    assert.equal(e.details.column, 8);
    assert.equal(
      describeError(e, translator('de'), 'x-Komponente von a(u)'),
      'x-Komponente von a(u): „1,5“ kann zwei Argumente oder ein Dezimalkomma sein: Schreiben Sie 1.5 für die Zahl oder „1, 5“ (mit Leerzeichen nach dem Komma) für zwei Argumente (Spalte 8).',
    );
  }
});

test('argument checks meant for programmers are said by their kind, never in English on a German page', () => {
  try {
    RuledSurface.fromSegments('nope');
    assert.fail('accepted');
  } catch (e) {
    assert.equal(e.details.reason, 'text');
    assert.equal(describeError(e, translator('de')), 'Ein Wert ist hier nicht verwendbar.');
  }
});

test('numbers are written exactly as Intl.NumberFormat writes them in English and German, rounding ties as it does', () => {
  const intl = (lang) => ({
    decimal: new Intl.NumberFormat(lang, { minimumFractionDigits: 3, maximumFractionDigits: 3 }),
    integer: new Intl.NumberFormat(lang, { maximumFractionDigits: 0, useGrouping: true }),
  });
  // a seeded walk over every magnitude the formats see, with decimal ties (…5 in the fourth place)
  let seed = 12345;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2 ** 31;
    return seed / 2 ** 31;
  };
  for (const lang of ['en', 'de']) {
    const { format } = translator(lang);
    const ref = intl(lang);
    const expect = (x) => (Number.isInteger(x) ? ref.integer.format(x) : ref.decimal.format(x)).replace('-', '−');
    const values = [0, -0, 0.1, -0.1, 999.9995, -999.9996, 0.1005, 144.2945, 1e15 - 1, 1234567];
    for (let k = 0; k < 20000; k++) {
      const x = (random() - 0.5) * 2 * 10 ** Math.floor(random() * 16);
      values.push(Math.round(x), x, (Math.round(random() * 2e6) / 2000) * (random() < 0.5 ? -1 : 1));
    }
    for (const x of values) {
      const a = Math.abs(x);
      if ((Number.isInteger(x) && a < 1e15) || (a >= 0.1 && a < 1000))
        assert.equal(format(x), expect(x), `${lang} ${x}`);
    }
  }
});

test('the page loads a language other than English when it needs it (i18n/translate.js); i18n/index.js has every one', async () => {
  const lazy = await import('../../www/i18n/translate.js');
  const { LANGUAGE_CODES } = await import('../../www/i18n/index.js');
  assert.deepEqual(lazy.LANGUAGE_CODES, LANGUAGE_CODES);
  // (index.js, imported above, added German already; the loader's result is the same table)
  assert.equal(await lazy.loadLanguage('de'), true);
  assert.equal(lazy.translator('de').t('view.fit'), de['view.fit']);
  assert.equal(await lazy.loadLanguage('xx'), false);
  assert.equal(lazy.translator('xx').t('view.fit'), en['view.fit']);
});
