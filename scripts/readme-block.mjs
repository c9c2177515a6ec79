// A generated block of the README: the text between <!-- name:begin --> and <!-- name:end -->,
// written by a script (the benchmarks, the table of the paper's figures) and never by hand.
import { readFileSync, writeFileSync } from 'node:fs';

export const README = new URL('../README.md', import.meta.url);

/**
 * `readme` with the block `name` replaced by `body` (markers kept); throws if the block is missing.
 * @param {string} readme @param {string} name @param {string} body
 */
export function withBlock(readme, name, body) {
  const [begin, end] = [`<!-- ${name}:begin -->`, `<!-- ${name}:end -->`];
  const [start, stop] = [readme.indexOf(begin), readme.indexOf(end)];
  if (start < 0 || stop < start) throw new Error(`README.md has no ${begin} … ${end} block`);
  return `${readme.slice(0, start)}${begin}\n${body}\n${readme.slice(stop)}`;
}

/**
 * Rewrites the block `name` of README.md with `body`; returns whether the file changed.
 * @param {string} name @param {string} body
 */
export function rewriteBlock(name, body) {
  const readme = readFileSync(README, 'utf8');
  const next = withBlock(readme, name, body);
  if (next !== readme) writeFileSync(README, next);
  return next !== readme;
}
