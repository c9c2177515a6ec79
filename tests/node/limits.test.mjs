// Every limit of the page is in www/limits.js (as the core's are in src/tolerance.rs), and a text
// quotes it, never retypes it: a text gets a {max}-style placeholder filled from limits.js where
// it is said (or, for a text said by key alone — a readout label, a claim, an explanation — its
// table interpolates the constant of limits.js). Fails on a MAX_…/MIN_… constant (or a …_LIMIT,
// …_THRESHOLD, …_TOLERANCE) defined outside limits.js, and on a text of any language (or an
// exercise's English reason, task/format.js) that writes a number equal to a page limit, unless
// NOT_LIMITS says what else that number is there. Limits below 10 (3 hints, 6 conditions, 8
// steps) are left out of the text check: such small numbers are everywhere in the paper's texts
// ("Fig. 3", "6 numbers per ruling", "n = 3, 4") and a text may write them as words.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import * as LIMITS from '../../www/limits.js';

const WWW = fileURLToPath(new URL('../../www/', import.meta.url));

/** Numbers in texts that equal a limit but mean something else there: [value, keys, what it is]. */
const NOT_LIMITS = [
  [
    12,
    [
      'edit.from.strip',
      'paper.fig9.note',
      'paper.fig10.caption',
      'paper.fig10.note',
      'paper.ex3.caption',
      'strip.legend.given',
      'strip.describe',
      'strip.describeEdited',
      'strip.text',
    ],
    'Example 3’s 12 rulings and n = 12 (the paper’s data), not TURNING_STEPS',
  ],
  [10, ['milling.text'], 'the figure’s scale (1 unit = 10 mm), not HANDLE_REACH or EDIT_BOX'],
  [50, ['task.check.notNumber'], 'an example of a number to type, not TASK_SAMPLES'],
  [
    0.1,
    ['convergence.readout.delta01', 'isometry.claim.helical'],
    'the index 0,1 and the paper’s 0.1, not ANSWER_CLOSE',
  ],
  [
    0.2,
    ['curves.claim.sharp', 'curves.text'],
    'the largest four-point tension w the claim covers, the end of the w slider, not FINE_DRAG',
  ],
  [16, ['boot.noWasm'], 'Safari 16.4 (German reads it as 16 and 4), not SNAP_REACH_COARSE'],
];

/** Every .js file under `dir`. */
function sources(/** @type {string} */ dir) {
  /** @type {string[]} */
  const out = [];
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) out.push(...sources(path));
    else if (name.endsWith('.js')) out.push(path);
  }
  return out;
}

/** The limits a text could retype: name by value (limits of 10 and more, and every non-integer). */
function limitValues(/** @type {Record<string, unknown>} */ limits) {
  /** @type {Map<number, string[]>} */
  const byValue = new Map();
  for (const [name, value] of Object.entries(limits))
    if (typeof value === 'number' && (value >= 10 || !Number.isInteger(value)))
      byValue.set(value, [...(byValue.get(value) ?? []), name]);
  return byValue;
}

/** References to the paper and equation numbers: "Fig. 3", "Figs. 2–3", "Example 1", "(12)", "(13)–(15)". */
const REFERENCE =
  /\b(?:Figs?\.|Abb\.|Examples?|Beispiele?|Sections?|Abschnitte?|Propositions?|Satz|Sätze|Equations?|Gleichung(?:en)?)\s*\d+(?:\s*(?:[–-]|and|und|,)\s*\d+)*|\(\d+\)(?:\s*[–-]\s*\(\d+\))?/g;

/**
 * The numbers a text writes (markup, MathML and references to the paper left out), in the
 * language's notation: "65,536" and "10 000" grouped, "0,17" a decimal in German, "1e12", and
 * "64 KiB" as 65536; the base of a power ("10⁻³") is no number of its own.
 * @param {string} text
 * @param {string} lang
 * @returns {Array<{value: number, written: string}>}
 */
function numbersIn(text, lang) {
  const [group, point] = lang === 'de' ? ['.', ','] : [',', '.'];
  const plain = text
    .replace(/<math[\s\S]*?<\/math>/g, ' ')
    .replace(/<[^>]+>/g, ' ')
    .replace(/&\w+;/g, ' ')
    .replace(REFERENCE, ' ');
  const esc = (/** @type {string} */ c) => `\\${c}`;
  const number = new RegExp(
    `(?<![\\w${esc(group)}${esc(point)}/^])(\\d{1,3}(?:[${esc(group)} \\u00a0\\u2009\\u202f]\\d{3})+(?!\\d)|\\d+)(?:${esc(point)}(\\d+))?(?:e(-?\\d+))?(\\s*KiB)?(?![\\d/⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺^])`,
    'g',
  );
  return [...plain.matchAll(number)].map((m) => {
    const whole = m[1].replace(/\D/g, '');
    let value = Number(`${whole}${m[2] ? `.${m[2]}` : ''}${m[3] ? `e${m[3]}` : ''}`);
    if (m[4]) value *= 1024;
    return { value, written: m[0].trim() };
  });
}

/**
 * The texts of a source: an object literal's keys and their texts (the literal parts: what a
 * template interpolates is quoted, not written), for each `export default {…}` of a table and
 * each `const ENGLISH = {…}`.
 * @param {string} name
 * @param {string} source
 */
function textsOf(name, source) {
  const sf = ts.createSourceFile(name, source, ts.ScriptTarget.Latest, true);
  /** @type {Array<{key: string, text: string}>} */
  const out = [];
  const take = (/** @type {import('typescript').ObjectLiteralExpression} */ o) => {
    for (const p of o.properties) {
      if (!ts.isPropertyAssignment(p) || !(ts.isStringLiteral(p.name) || ts.isIdentifier(p.name))) continue;
      const v = p.initializer;
      if (ts.isStringLiteral(v) || ts.isNoSubstitutionTemplateLiteral(v)) out.push({ key: p.name.text, text: v.text });
      else if (ts.isTemplateExpression(v))
        out.push({ key: p.name.text, text: [v.head.text, ...v.templateSpans.map((s) => s.literal.text)].join(' ') });
    }
  };
  const visit = (/** @type {import('typescript').Node} */ n) => {
    if (ts.isExportAssignment(n) && ts.isObjectLiteralExpression(n.expression)) take(n.expression);
    if (ts.isVariableDeclaration(n) && ts.isIdentifier(n.name) && n.name.text === 'ENGLISH' && n.initializer) {
      let e = n.initializer;
      while (ts.isParenthesizedExpression(e) || ts.isAsExpression(e)) e = e.expression;
      if (ts.isObjectLiteralExpression(e)) take(e);
    }
    ts.forEachChild(n, visit);
  };
  visit(sf);
  return out;
}

/**
 * Numbers that retype a limit in `texts` ({lang, key, text}).
 * @param {Array<{lang: string, key: string, text: string}>} texts
 * @param {Record<string, unknown>} limits
 */
function retyped(texts, limits) {
  const byValue = limitValues(limits);
  const out = [];
  for (const { lang, key, text } of texts)
    for (const { value, written } of numbersIn(text, lang)) {
      const names = byValue.get(value);
      if (!names) continue;
      if (NOT_LIMITS.some(([v, keys]) => v === value && /** @type {string[]} */ (keys).includes(key))) continue;
      out.push(`${lang} "${key}": "${written}" is ${names.join(' = ')}: quote it ({max} filled from limits.js)`);
    }
  return out;
}

/** Every text of the page: each language's tables, and the exercises' English reasons. */
function pageTexts() {
  const texts = [];
  for (const lang of readdirSync(join(WWW, 'i18n')).filter((d) => statSync(join(WWW, 'i18n', d)).isDirectory()))
    for (const file of sources(join(WWW, 'i18n', lang)))
      for (const t of textsOf(file, readFileSync(file, 'utf8'))) texts.push({ lang, ...t });
  const format = join(WWW, 'task/format.js');
  for (const t of textsOf(format, readFileSync(format, 'utf8'))) texts.push({ lang: 'en', ...t });
  return texts;
}

test('no limit of the page is defined outside www/limits.js', () => {
  const files = sources(WWW).filter((f) => relative(WWW, f) !== 'limits.js');
  assert.ok(files.length > 100, `only ${files.length} files read`);
  const definition =
    /^\s*(?:export\s+)?const\s+((?:MAX|MIN)_[A-Z0-9_]*|[A-Z0-9_]+_(?:LIMIT|THRESHOLD|TOLERANCE))\s*=/gm;
  const found = files.flatMap((f) =>
    [...readFileSync(f, 'utf8').matchAll(definition)].map((m) => `www/${relative(WWW, f)}: ${m[1]}`),
  );
  assert.deepEqual(found, []);
  // and the pattern finds what it is for
  assert.equal([...'const MAX_X = 3;\nexport const LINE_LIMIT = 4;\n'.matchAll(definition)].length, 2);
});

test('no text retypes a limit of the page: it quotes it', () => {
  const texts = pageTexts();
  assert.ok(texts.length > 1800, `only ${texts.length} texts read`);
  const numbers = texts.reduce((n, { text, lang }) => n + numbersIn(text, lang).length, 0);
  assert.ok(numbers > 300, `only ${numbers} numbers found in the texts`);
  assert.deepEqual(retyped(texts, LIMITS), []);
  // each exception still names a number its text writes (an exception no text needs goes)
  for (const [value, keys] of NOT_LIMITS)
    for (const key of /** @type {string[]} */ (keys))
      assert.ok(
        texts.some((t) => t.key === key && numbersIn(t.text, t.lang).some((n) => n.value === value)),
        `NOT_LIMITS: "${key}" writes no ${value}`,
      );
});

test('the text check finds a retyped limit in every notation, and passes references and data by', () => {
  const limits = { MAX_LINK_RULINGS: 200, MAX_HASH: 65536, MAX_TASK_NUMBER: 1e12, TURNING_STEPS: 12, KEY_STEP: 0.02 };
  const found = (/** @type {string} */ text, lang = 'en', key = 'x.y') => retyped([{ lang, key, text }], limits);
  assert.equal(found('This import has more than 200 rulings.').length, 1);
  assert.equal(found('Dieser Link ist länger als 64 KiB.', 'de').length, 1);
  assert.equal(found('longer than 65,536 characters').length, 1);
  assert.equal(found('länger als 65.536 Zeichen', 'de').length, 1);
  assert.equal(found('at most 1e12').length, 1);
  assert.equal(found('after 12 steps').length, 1);
  assert.equal(found('a step of 0,02', 'de').length, 1);
  assert.deepEqual(found('Fig. 12, Figs. 11–12, (12), Example 12, 0.200, 1/12, R_12, 2000'), []);
  assert.deepEqual(found('1.89·10⁻³, 10^3'), []);
  assert.deepEqual(found('n = 12 rulings', 'en', 'strip.describe'), []);
  assert.deepEqual(found('0,2 und 12,5', 'de'), []);
});
