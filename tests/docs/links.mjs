// The docs check (`npm test`, step "docs", after scripts/docs.sh built site/): every relative
// href and src of every page of the site resolves to a file, and every #fragment names an id
// (or a name) in its target; README.md's links into the repository resolve, and a link into
// docs/src/ is checked, anchor included, against the page the book makes of it; every generated
// block is on the page scripts/doc-block.mjs names, once, and on no other page.
//   node tests/docs/links.mjs [site]
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { BLOCKS, BOOK } from '../../scripts/doc-block.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const SITE = resolve(process.argv[2] ?? join(ROOT, 'site'));
/** @type {string[]} */
const problems = [];

/** Every file under `dir` whose name ends with `ext`. @param {string} dir @param {string} ext @returns {string[]} */
function files(dir, ext) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? files(join(dir, e.name), ext) : e.name.endsWith(ext) ? [join(dir, e.name)] : [],
  );
}

/** The ids and names of an HTML page, read once. @type {Map<string, Set<string>>} */
const anchors = new Map();
/** @param {string} file */
function anchorsOf(file) {
  let set = anchors.get(file);
  if (!set) {
    const html = readFileSync(file, 'utf8');
    set = new Set([...attributes(html, /^(?:id|name)$/)].map((a) => decode(a.value)));
    anchors.set(file, set);
  }
  return set;
}

/**
 * The attributes named by `names` of the tags of `html`, with their offsets: not what a code
 * block shows as text (where < is escaped), nor the text of a script. Values may be quoted or
 * not (rustdoc writes them bare).
 * @param {string} html @param {RegExp} names
 */
function* attributes(html, names) {
  const markup = html.replace(
    /(<script\b[^>]*>)([\s\S]*?)(<\/script>)/gi,
    (_, open, body, close) => open + body.replace(/[^\n]/g, ' ') + close,
  );
  for (const tag of markup.matchAll(/<[a-zA-Z][\w-]*(\s[^>]*)?>/g)) {
    for (const a of (tag[1] ?? '').matchAll(/([\w:-]+)\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s"'>]+))/g)) {
      if (names.test(a[1])) yield { name: a[1], value: a[2] ?? a[3] ?? a[4], index: /** @type {number} */ (tag.index) };
    }
  }
}

/** @param {string} s */
function decode(s) {
  const text = s
    .replace(/&amp;/g, '&')
    .replace(/&quot;/g, '"')
    .replace(/&#39;/g, "'")
    .replace(/&lt;/g, '<');
  try {
    return decodeURIComponent(text);
  } catch {
    return text;
  }
}

/** A link that leaves the site (or the repository): not checked. @param {string} href */
const external = (href) => /^[a-z][a-z0-9+.-]*:/i.test(href) || href.startsWith('//');

/**
 * Checks one relative link of `from`; `where` says where it is written.
 * @param {string} from @param {string} href @param {string} where
 */
function checkHtmlLink(from, href, where) {
  const [pathAndQuery, fragment] = splitFragment(decode(href));
  const path = pathAndQuery.split('?')[0];
  let target = path === '' ? from : resolve(dirname(from), path);
  if (!target.startsWith(SITE)) {
    problems.push(`${where}: ${href} leaves the site`);
    return;
  }
  if (existsSync(target) && statSync(target).isDirectory()) target = join(target, 'index.html');
  if (!existsSync(target)) {
    problems.push(`${where}: ${href} → no file ${relative(ROOT, target)}`);
    return;
  }
  if (!fragment || !target.endsWith('.html')) return;
  // rustdoc's source pages take a range of lines, "#12-20": both ends are lines of the page
  const ids = /^\d+-\d+$/.test(fragment) ? fragment.split('-') : [fragment];
  for (const id of ids)
    if (!anchorsOf(target).has(id)) problems.push(`${where}: ${href} → ${relative(ROOT, target)} has no id "${id}"`);
}

/** @param {string} href @returns {[string, string]} */
function splitFragment(href) {
  const hash = href.indexOf('#');
  return hash < 0 ? [href, ''] : [href.slice(0, hash), href.slice(hash + 1)];
}

// 1. the site's pages
if (!existsSync(join(SITE, 'index.html'))) {
  console.error(`docs check: no site in ${SITE}; run npm run docs first`);
  process.exit(1);
}
// (mdBook's 404.html resolves its links against the address the site is served from: not here)
const pages = files(SITE, '.html').filter((f) => f !== join(SITE, '404.html'));
let links = 0;
for (const page of pages) {
  const html = readFileSync(page, 'utf8');
  for (const a of attributes(html, /^(?:href|src)$/)) {
    const href = a.value;
    if (external(href) || href === '#' || href === '') continue;
    links++;
    const line = html.slice(0, a.index).split('\n').length;
    checkHtmlLink(page, href, `${relative(ROOT, page)}:${line}`);
  }
}

// 2. README.md's Markdown links
const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
const prose = readme.replace(/^```[\s\S]*?^```/gm, (block) => block.replace(/[^\n]/g, ' '));
let readmeLinks = 0;
for (const m of prose.matchAll(/!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)/g)) {
  const href = m[1];
  if (external(href)) continue;
  readmeLinks++;
  const where = `README.md:${prose.slice(0, m.index).split('\n').length}`;
  const [path, fragment] = splitFragment(href);
  const target = resolve(ROOT, path);
  if (!target.startsWith(ROOT) || !existsSync(target)) {
    problems.push(`${where}: ${href} → no file ${path}`);
    continue;
  }
  const book = relative(fileURLToPath(BOOK), target);
  if (fragment && path.endsWith('.md') && !book.startsWith('..')) {
    const html = join(SITE, book.replace(/\.md$/, '.html'));
    if (!existsSync(html)) problems.push(`${where}: ${href} → the book has no page ${relative(ROOT, html)}`);
    else if (!anchorsOf(html).has(decode(fragment)))
      problems.push(`${where}: ${href} → ${relative(ROOT, html)} has no id "${fragment}"`);
  } else if (fragment) problems.push(`${where}: ${href} → an anchor outside the book cannot be checked`);
}

// 3. the generated blocks
const sources = [join(ROOT, 'README.md'), ...files(fileURLToPath(BOOK), '.md')];
for (const file of sources) {
  // markers in code (``, ```) are shown, not blocks
  const text = readFileSync(file, 'utf8')
    .replace(/^```[\s\S]*?^```/gm, (code) => code.replace(/[^\n]/g, ' '))
    .replace(/`[^`\n]*`/g, (code) => ' '.repeat(code.length));
  for (const m of text.matchAll(/<!-- ([\w-]+):(begin|end) -->/g)) {
    const [, name, kind] = m;
    const home = /** @type {Record<string, string>} */ (BLOCKS)[name];
    const where = `${relative(ROOT, file)}:${text.slice(0, m.index).split('\n').length}`;
    if (!home) problems.push(`${where}: block "${name}" is not listed in scripts/doc-block.mjs`);
    else if (resolve(fileURLToPath(BOOK), home) !== file)
      problems.push(`${where}: block "${name}" belongs on docs/src/${home}`);
    else if (text.split(`<!-- ${name}:${kind} -->`).length !== 2)
      problems.push(`${where}: block "${name}" has more than one ${kind} marker`);
  }
}
for (const [name, home] of Object.entries(BLOCKS)) {
  const text = readFileSync(new URL(home, BOOK), 'utf8');
  const [begin, end] = [text.indexOf(`<!-- ${name}:begin -->`), text.indexOf(`<!-- ${name}:end -->`)];
  if (begin < 0 || end < begin) problems.push(`docs/src/${home}: block "${name}" is missing`);
}

if (problems.length) {
  for (const p of problems) console.error(p);
  console.error(`docs check: ${problems.length} broken links, anchors or blocks`);
  process.exit(1);
}
console.log(
  `docs check: ${links} links of ${pages.length} pages and ${readmeLinks} of README.md resolve; ${Object.keys(BLOCKS).length} generated blocks in place`,
);
