// Every English text of the page and of <ruled-view>, by key: the files of this folder, one per
// group of key prefixes (the prefixes each holds are at its top; the same files for every
// language). tests/node/languages.test.mjs fails on a key defined twice, one a language lacks,
// a key outside its file's prefixes, and placeholders that differ between languages.
import * as tables from './tables.js';

/** The tables as one (their keys are disjoint: tests/node/languages.test.mjs). */
export default /** @type {Record<string, string>} */ (Object.assign({}, ...Object.values(tables)));
