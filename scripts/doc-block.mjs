// A generated block of the book: the text between <!-- name:begin --> and <!-- name:end --> on
// one page of docs/src/, written by a script (the benchmarks, the table of the paper's figures)
// and never by hand. BLOCKS says which page holds which block; the docs check
// (tests/docs/links.mjs) fails on a block that is missing, on a page other than its own, or not
// listed here.
import { readFileSync, writeFileSync } from 'node:fs';

/** The book's sources. */
export const BOOK = new URL('../docs/src/', import.meta.url);

/** Every generated block and the page of docs/src/ it lives on. */
export const BLOCKS = /** @type {const} */ ({
  paper: 'teaching/paper.md',
  bench: 'internals/benchmarks.md',
  'bench-instructions': 'internals/benchmarks.md',
  // (written by bench/python.py)
  'bench-python': 'internals/benchmarks.md',
  'bench-page': 'internals/page-speed.md',
  'bench-drag': 'internals/page-speed.md',
  'bench-klein': 'internals/page-speed.md',
  'bench-lighthouse': 'internals/page-speed.md',
  sizes: 'internals/sizes.md',
});

/** @typedef {keyof typeof BLOCKS} BlockName */

/** The file of the page that holds the block `name`. @param {BlockName} name */
export const pageOf = (name) => new URL(BLOCKS[name], BOOK);

/**
 * `text` with the block `name` replaced by `body` (markers kept); throws if the block is missing.
 * @param {string} text @param {string} name @param {string} body
 */
export function withBlock(text, name, body) {
  const [begin, end] = [`<!-- ${name}:begin -->`, `<!-- ${name}:end -->`];
  const [start, stop] = [text.indexOf(begin), text.indexOf(end)];
  if (start < 0 || stop < start) throw new Error(`the page has no ${begin} … ${end} block`);
  return `${text.slice(0, start)}${begin}\n${body}\n${text.slice(stop)}`;
}

/**
 * Rewrites the block `name` on its page with `body`; returns whether the page changed.
 * @param {BlockName} name @param {string} body
 */
export function rewriteBlock(name, body) {
  const file = pageOf(name);
  const text = readFileSync(file, 'utf8');
  let next;
  try {
    next = withBlock(text, name, body);
  } catch (e) {
    throw new Error(`docs/src/${BLOCKS[name]}: ${/** @type {Error} */ (e).message}`);
  }
  if (next !== text) writeFileSync(file, next);
  return next !== text;
}
