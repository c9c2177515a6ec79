// The languages' tables (www/i18n/<code>/): the same files in every language, each one object
// literal whose keys lie under the prefixes named at its top ("// Keys: app.*, boot.*, …"; the
// longest matching prefix, or a whole key, says which file holds a key). The sources are parsed
// (with TypeScript's parser), since an object literal or a spread silently keeps the last value
// of a key defined twice. Fails on a key defined twice (in one file or in two files of one
// language), a key one language has and another lacks, a key outside its file's prefixes, and a
// {placeholder} that differs between languages; the checks are shown to fail on broken tables.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import ts from 'typescript';

const I18N = fileURLToPath(new URL('../../www/i18n/', import.meta.url));
/** A file of a language longer than this is split by prefix (the house's size of a file). */
const MOST_LINES = 400;

/** Placeholders of a text: {name}, and {name:one:many}. */
const placeholders = (/** @type {string} */ text) =>
  [...new Set([...text.matchAll(/\{(\w+)(?::[^}]*)?\}/g)].map((m) => m[1]))].sort();

/**
 * The prefixes a file's header names: "// Keys: a.*, b.c" and continuation lines "//   d.*".
 * "a.*" is a prefix ("a."), "b.c" a whole key.
 * @param {string} source
 */
function declared(source) {
  const lines = source.split('\n');
  const start = lines.findIndex((l) => l.startsWith('// Keys:'));
  if (start < 0) return null;
  let text = lines[start].slice('// Keys:'.length);
  for (let k = start + 1; k < lines.length && /^\/\/ {2,}\S/.test(lines[k]); k++) text += ` ${lines[k].slice(2)}`;
  return text
    .split(/[\s,]+/)
    .filter(Boolean)
    .map((p) => (p.endsWith('*') ? { prefix: p.slice(0, -1), whole: false } : { prefix: p, whole: true }));
}

/**
 * The keys and texts of a table's source: its `export default { … }`, every property a quoted
 * key and a text (a string, or a template whose ${…} parts are markup: their placeholders are
 * read from the literal parts).
 * @param {string} name
 * @param {string} source
 * @returns {{entries: Array<{key: string, line: number, text: string}>, problems: string[]}}
 */
function parseTable(name, source) {
  const sf = ts.createSourceFile(name, source, ts.ScriptTarget.Latest, true);
  const problems = [];
  const entries = [];
  const exported = sf.statements.find((s) => ts.isExportAssignment(s));
  if (!exported || !ts.isObjectLiteralExpression(exported.expression))
    return { entries, problems: [`${name}: no "export default { … }"`] };
  for (const p of exported.expression.properties) {
    const line = sf.getLineAndCharacterOfPosition(p.getStart()).line + 1;
    if (
      !ts.isPropertyAssignment(p) ||
      !(ts.isStringLiteral(p.name) || ts.isNoSubstitutionTemplateLiteral(p.name) || ts.isIdentifier(p.name))
    ) {
      problems.push(`${name}:${line}: not a key and its text (a spread or a computed key hides what is defined)`);
      continue;
    }
    const v = p.initializer;
    let text;
    if (ts.isStringLiteral(v) || ts.isNoSubstitutionTemplateLiteral(v)) text = v.text;
    else if (ts.isTemplateExpression(v)) text = [v.head.text, ...v.templateSpans.map((s) => s.literal.text)].join('\0');
    else {
      problems.push(`${name}:${line}: the text of "${p.name.text}" is not a string or a template`);
      continue;
    }
    entries.push({ key: p.name.text, line, text });
  }
  return { entries, problems };
}

/**
 * Everything wrong with a set of languages' tables.
 * @param {Record<string, Record<string, string>>} sources   language → file name → source
 *   (index.js and tables.js left out), English first
 * @returns {string[]}
 */
function problems(sources) {
  const out = [];
  const langs = Object.keys(sources);
  const [first] = langs;
  /** language → key → {file, text} */
  const tables = {};
  for (const lang of langs) {
    const files = sources[lang];
    if (lang !== first) {
      const a = Object.keys(sources[first]).sort().join(', ');
      const b = Object.keys(files).sort().join(', ');
      if (a !== b) out.push(`${lang}: the files are ${b}, ${first}'s are ${a}`);
    }
    /** @type {Array<{prefix: string, whole: boolean, file: string}>} */
    const patterns = [];
    for (const [file, source] of Object.entries(files)) {
      const lines = source.split('\n').length;
      if (lines > MOST_LINES) out.push(`${lang}/${file}: ${lines} lines, more than ${MOST_LINES}: split it by prefix`);
      const d = declared(source);
      if (!d) out.push(`${lang}/${file}: no "// Keys: …" line naming the prefixes it holds`);
      for (const p of d ?? []) {
        const other = patterns.find((q) => q.prefix === p.prefix && q.whole === p.whole);
        if (other) out.push(`${lang}: ${p.prefix}${p.whole ? '' : '*'} is named by ${other.file} and ${file}`);
        patterns.push({ ...p, file });
      }
      if (lang !== first && sources[first][file] !== undefined) {
        const mine = JSON.stringify(d);
        const theirs = JSON.stringify(declared(sources[first][file]));
        if (mine !== theirs) out.push(`${lang}/${file}: its "// Keys:" differ from ${first}/${file}'s`);
      }
    }
    /** @type {Record<string, {file: string, text: string}>} */
    const table = {};
    tables[lang] = table;
    for (const [file, source] of Object.entries(files)) {
      const parsed = parseTable(`${lang}/${file}`, source);
      out.push(...parsed.problems);
      for (const { key, line, text } of parsed.entries) {
        const before = table[key];
        if (before)
          out.push(
            `${lang}: "${key}" is defined twice: ${before.file === file ? `twice in ${file}` : `in ${before.file} and ${file}`} (line ${line}: the later one wins)`,
          );
        else table[key] = { file, text };
        // the file whose longest prefix (or whole key) matches the key holds it
        let best = null;
        for (const p of patterns)
          if (
            (p.whole ? key === p.prefix : key.startsWith(p.prefix)) &&
            (!best || p.prefix.length > best.prefix.length)
          )
            best = p;
        if (!best) out.push(`${lang}/${file}:${line}: "${key}" is under no prefix of any file's "// Keys:"`);
        else if (best.file !== file)
          out.push(
            `${lang}/${file}:${line}: "${key}" belongs in ${best.file} (${best.prefix}${best.whole ? '' : '*'})`,
          );
      }
    }
  }
  for (const lang of langs.slice(1)) {
    for (const key of Object.keys(tables[first]))
      if (!(key in tables[lang])) out.push(`${lang}: "${key}" is missing (${first}/${tables[first][key].file} has it)`);
    for (const key of Object.keys(tables[lang]))
      if (!(key in tables[first]))
        out.push(`${lang}: "${key}" is not a key of ${first} (in ${tables[lang][key].file})`);
    for (const [key, { text }] of Object.entries(tables[first])) {
      const other = tables[lang][key];
      if (!other) continue;
      const a = placeholders(text).join(', ');
      const b = placeholders(other.text).join(', ');
      if (a !== b) out.push(`"${key}": ${first} has the placeholders {${a}}, ${lang} {${b}}`);
    }
  }
  return out;
}

/** The languages' folders, English first, and each one's table files (not index.js, nor tables.js, which gathers them). */
function readSources() {
  const langs = readdirSync(I18N)
    .filter((name) => statSync(join(I18N, name)).isDirectory())
    .sort((a, b) => (a === 'en' ? -1 : b === 'en' ? 1 : a.localeCompare(b)));
  return Object.fromEntries(
    langs.map((lang) => [
      lang,
      Object.fromEntries(
        readdirSync(join(I18N, lang))
          .filter((f) => f.endsWith('.js') && f !== 'index.js' && f !== 'tables.js')
          .sort()
          .map((f) => [f, readFileSync(join(I18N, lang, f), 'utf8')]),
      ),
    ]),
  );
}

test('the tables of every language: no key twice, each under its file’s prefixes, every key in every language, the same placeholders', () => {
  const sources = readSources();
  assert.deepEqual(Object.keys(sources), ['en', 'de']);
  assert.ok(Object.keys(sources.en).length >= 8, `only ${Object.keys(sources.en).length} files in en/`);
  const keys = Object.values(sources.en).reduce((n, s) => n + parseTable('', s).entries.length, 0);
  assert.ok(keys > 900, `only ${keys} keys read from en/`);
  assert.deepEqual(problems(sources), []);
});

test('each language’s index.js assembles every file of its folder, and the page offers every language', async () => {
  const sources = readSources();
  const { LANGUAGE_CODES } = await import('../../www/i18n/translate.js');
  assert.deepEqual([...LANGUAGE_CODES].sort(), Object.keys(sources).sort());
  for (const [lang, files] of Object.entries(sources)) {
    const table = (await import(pathToFileURL(join(I18N, lang, 'index.js')).href)).default;
    const union = new Set();
    for (const file of Object.keys(files)) {
      const part = (await import(pathToFileURL(join(I18N, lang, file)).href)).default;
      for (const [key, text] of Object.entries(part)) {
        union.add(key);
        assert.equal(table[key], text, `${lang}/index.js: "${key}" is not ${file}'s text`);
      }
    }
    assert.deepEqual(Object.keys(table).sort(), [...union].sort(), `${lang}/index.js does not hold every file`);
  }
});

test('notation, written alike in every language, is read by every translator and defined by no language', async () => {
  const { default: notation } = await import('../../www/i18n/notation.js');
  const { translator, loadLanguage, LANGUAGE_CODES } = await import('../../www/i18n/translate.js');
  assert.ok(Object.keys(notation).length > 0);
  for (const lang of LANGUAGE_CODES) {
    assert.ok(await loadLanguage(lang));
    const table = (await import(pathToFileURL(join(I18N, lang, 'index.js')).href)).default;
    const { t, has } = translator(lang);
    for (const [key, text] of Object.entries(notation)) {
      assert.ok(!(key in table), `${lang} defines "${key}", which is notation (i18n/notation.js)`);
      assert.equal(t(key), text, `${lang}: ${key}`);
      assert.ok(has(key), `${lang}: has(${key})`);
    }
  }
});

test('each check fails on tables that break it', () => {
  const en = {
    'a.js': `// Keys: a.*\nexport default {\n  'a.x': 'one {n}',\n  'a.x': 'two {n}',\n  'a.w': 'w {m}',\n};\n`,
    'b.js': `// Keys: b.*, a.y\nexport default {\n  'a.y': 'y',\n  'a.w': 'again',\n  'a.z': 'z',\n  'c.q': 'c',\n  ...more,\n};\n`,
  };
  const de = {
    'a.js': `// Keys: a.*\nexport default {\n  'a.x': 'eins {n}',\n  'a.w': 'w {k}',\n  'a.v': 'v',\n};\n`,
    'b.js': `// Keys: b.*\nexport default {\n  'a.y': \`y \${q}\`,\n};\n`,
  };
  const found = problems({ en, de });
  const expect = [
    /^en: "a\.x" is defined twice: twice in a\.js/,
    /^en: "a\.w" is defined twice: in a\.js and b\.js/,
    /^en\/b\.js:5: "a\.z" belongs in a\.js \(a\.\*\)/,
    /^en\/b\.js:6: "c\.q" is under no prefix/,
    /^en\/b\.js:7: not a key and its text/,
    /^de\/b\.js: its "\/\/ Keys:" differ from en\/b\.js's/,
    /^de\/b\.js:3: "a\.y" belongs in a\.js/,
    /^de: "a\.z" is missing/,
    /^de: "a\.v" is not a key of en/,
    /^"a\.w": en has the placeholders \{m\}, de \{k\}/,
  ];
  for (const e of expect)
    assert.ok(
      found.some((f) => e.test(f)),
      `not reported: ${e}\n${found.join('\n')}`,
    );
  assert.deepEqual(problems({ en: { 'a.js': `// Keys: a.*\nexport default { 'a.x': 'x' };\n` } }), []);
  const long = `// Keys: a.*\nexport default {\n${"  'a.x': 'x',\n".repeat(1)}${'\n'.repeat(MOST_LINES)}};\n`;
  assert.match(problems({ en: { 'a.js': long } }).join('\n'), /more than 400/);
});

test('one rendering of subscripts everywhere: every label with one — the tables’ texts, the scenes’ labels and readouts, the exercises — shows it lowered, as <sub> in the page and in Unicode’s subscripts as plain text, never as m_{6} or m i', async () => {
  const { parseRich, plainRich, plainSubscripts } = await import('../../www/ui/richtext.js');
  const { translator } = await import('../../www/i18n/index.js');
  const { builtInTasks } = await import('../../www/task/builtin.js');
  const { say } = await import('../../www/task/format.js');
  const subscript = /[₀-ₜᵢ-ᵪⱼ]/u;
  /** Fails unless `text` has a subscript that plain text shows lowered, with no mark left. */
  const lowered = (/** @type {string} */ where, /** @type {string} */ text) => {
    const plain = plainRich(text);
    assert.doesNotMatch(plain, /[_{}]/, `${where}: "${text}" → "${plain}"`);
    assert.match(plain, subscript, `${where}: "${text}" → "${plain}"`);
    assert.ok(
      parseRich(text).some((p) => p.kind === 'sub'),
      `${where}: "${text}" has no <sub> in the page`,
    );
  };
  let checked = 0;
  for (const lang of ['en', 'de']) {
    const i18n = translator(lang);
    const table = /** @type {Record<string, string>} */ ((await import(`../../www/i18n/${lang}/index.js`)).default);
    for (const [key, text] of Object.entries(table)) {
      // texts with markup are HTML or MathML; an error quotes column names as written (tip_x)
      if (!/_[{\w]/.test(text) || /[<`]/.test(text) || key.startsWith('error.')) continue;
      // every placeholder filled with a number, as the page fills {i} and {j}
      const vars = Object.fromEntries([...text.matchAll(/\{(\w+)[}:]/g)].map((m) => [m[1], 6]));
      lowered(`${lang} ${key}`, i18n.t(key, vars));
      checked++;
    }
  }
  assert.ok(checked >= 80, `${checked} texts`);
  // the snap targets' names, as the tip and the live region show them
  const en = translator('en');
  assert.equal(plainRich(en.t('snap.striction', { i: '6' })), 'the striction point m₆');
  assert.equal(plainRich(en.t('snap.footpoint', { i: '6', j: '5' })), 'the footpoint f₆,₅');
  assert.equal(plainRich(en.t('readout.midpointError')), 'max |mᵢ − s(uᵢ)|');
  assert.equal(plainRich('x^2 + N_{i,i+1}'), 'x² + Nᵢ,ᵢ₊₁');
  // the labels of every scene's figure and its readouts (the notebook reads these as text)
  const ruledlab = (await import('./load.mjs')).default;
  assert.ok(ruledlab);
  const { SCENES } = await import('../../www/scenes/index.js');
  const { defaults } = await import('../../www/scene.js');
  const context = { t: en.t, format: en.format, lang: 'en' };
  let labels = 0;
  for (const scene of SCENES) {
    if (scene.id === 'large' || scene.id === 'data') continue;
    const built = /** @type {any} */ (await scene.create(defaults(scene), context));
    const texts = [
      ...(built.labels ?? []).map((/** @type {any} */ l) => [`${scene.id} label`, l.text]),
      ...(built.readouts ?? []).map((/** @type {any} */ r) => [`${scene.id} readout`, en.t(r.label)]),
    ];
    for (const [where, text] of texts)
      if (/_[{\w]/.test(text)) {
        lowered(where, text);
        labels++;
      }
  }
  assert.ok(labels >= 10, `${labels} labels of scenes`);
  // the exercises' texts: m_i said as mᵢ, in both languages
  for (const task of builtInTasks())
    for (const words of [task.title, task.prompt, ...task.hints, ...task.answers.map((a) => a.label)])
      for (const lang of ['en', 'de'])
        assert.doesNotMatch(say(words, lang), /_[{\w]/, `${task.id}: ${say(words, lang)}`);
  assert.equal(plainSubscripts('m_i and u^2'), 'mᵢ and u^2');
});

test('the 3D view’s accessible name lists the touch gestures as well as the keys and the mouse, in both languages', async () => {
  const { translator } = await import('../../www/i18n/index.js');
  const words = {
    en: ['arrow keys', 'wheel', 'one finger', 'two fingers', 'pinch'],
    de: ['Pfeiltasten', 'Mausrad', 'Finger', 'zwei', 'gespreizte'],
  };
  for (const [lang, need] of Object.entries(words)) {
    const label = translator(lang).t('view.label');
    for (const w of need) assert.ok(label.includes(w), `${lang}: view.label has no "${w}"`);
  }
});
