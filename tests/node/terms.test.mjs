// German as German line geometry writes it: the table of terms in the book (docs/src/guide/
// languages.md, between its "german terms" markers) is read, and every German text of the page and of
// the built-in exercises is held to it — the words the table rules out never appear (a word the
// paper's own caption uses stays in the captions the page quotes), and a term given with its
// synonym ("Kehllinie (Striktionslinie)") is introduced that way somewhere.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import de from '../../www/i18n/de/index.js';
import { builtInTasks } from '../../www/task/builtin.js';

const BOOK = new URL('../../docs/src/guide/languages.md', import.meta.url);

/** The table's rows: the German term and the words not to use (and whether captions may). */
function terms() {
  const text = readFileSync(BOOK, 'utf8');
  const block = /<!-- german terms [^>]*-->([\s\S]*?)<!-- end of german terms -->/.exec(text)?.[1] ?? '';
  return block
    .split('\n')
    .filter((line) => line.startsWith('|') && !/^\|\s*(English|---)/.test(line))
    .map((line) => {
      const [english, german, not] = line
        .split('|')
        .slice(1, 4)
        .map((c) => c.trim());
      const caption = /\(but in the paper's caption\)/.test(not);
      const words = not
        .replace(/\(but in the paper's caption\)/, '')
        .split(',')
        .map((w) => w.trim())
        .filter(Boolean);
      return { english, german, words, caption };
    });
}

/** Every German text: the page's tables by key, and the exercises' German fields. */
function germanTexts() {
  /** @type {Array<[string, string]>} */
  const out = Object.entries(/** @type {Record<string, string>} */ (de));
  const walk = (/** @type {unknown} */ value, /** @type {string} */ path) => {
    if (Array.isArray(value)) for (const [i, v] of value.entries()) walk(v, `${path}[${i}]`);
    else if (value && typeof value === 'object')
      for (const [k, v] of Object.entries(value)) {
        if (k === 'de' && typeof v === 'string') out.push([path, v]);
        else walk(v, `${path}.${k}`);
      }
  };
  for (const task of builtInTasks()) walk(task, `task ${task.id}`);
  return out;
}

/** The keys that quote the paper's captions (its menu names and its translated captions). */
const isCaption = (/** @type {string} */ key) => /^paper\.fig\d+(\.caption)?$/.test(key);

test('the table of German terms is there and has the terms this page needs', () => {
  const rows = terms();
  assert.ok(rows.length >= 15, `${rows.length} rows`);
  for (const needed of [
    'Regelschar',
    'Näherungsabwicklung',
    'Butterfly-Schema',
    'Kehllinie (Striktionslinie)',
    'Endpunktschema',
    'Geradenraumschema',
  ])
    assert.ok(
      rows.some((r) => r.german.includes(needed)),
      `the table has ${needed}`,
    );
});

test('no German text uses a word the table rules out (the paper’s captions may quote theirs)', () => {
  const texts = germanTexts();
  const wrong = [];
  for (const { words, caption } of terms())
    for (const word of words) {
      // as written, its first letter in either case (a sentence may start with it), in the text,
      // not in its markup
      const escaped = word.slice(1).replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
      const first = `[${word[0].toLowerCase()}${word[0].toUpperCase()}]`;
      const pattern = new RegExp(`(^|[^\\p{L}])${first}${escaped}`, 'u');
      for (const [key, text] of texts)
        if (pattern.test(text.replace(/<[^>]+>|\{[^}]*\}/g, '')) && !(caption && isCaption(key)))
          wrong.push(`${key}: "${word}"`);
    }
  assert.deepEqual(wrong, []);
});

test('every term given with its synonym is introduced so, and every term of the table is used', () => {
  const all = germanTexts()
    .map(([, text]) => text)
    .join('\n')
    .replace(/<[^>]+>/g, '');
  for (const { german } of terms()) {
    const synonym = /^(.*?) \((.*?)\)(.*)$/.exec(german);
    if (synonym) {
      const [, term, other, rest] = synonym;
      assert.ok(all.includes(`${term} (${other})${rest}`), `"${german}" is introduced with its synonym somewhere`);
    } else {
      // (an adjective in any of its endings: "variationellen Schemata")
      const stem = german.split(' ')[0].replace(/(es|er|en|e)$/, '');
      assert.ok(all.includes(stem), `"${german}" is used`);
    }
  }
});
