// Gives the two errors that wasm-bindgen's generated glue throws by itself a `code`, like every
// error of ruledlab's own (the book, "Errors and their codes"): an argument of the wrong class
// (`expected instance of RuledSurface`) becomes `invalid-argument`; calling a method of a freed
// object ("null pointer passed to rust") becomes `freed` with a message that says what happened;
// re-entrant use becomes `invalid-state`. Each edit must match the glue exactly once, so a
// wasm-bindgen upgrade that changes the glue fails the build instead of silently losing codes.
// The declarations get `/// <reference lib="esnext.disposable" />`: they declare
// `[Symbol.dispose]()` (for `using`), which needs that lib whatever the user's tsconfig says.
// The doc comments tsify derives from the Rust types come as Rust string literals (`\"ball\"`,
// `\u{304}`): they are read back to the text written. A name declared twice (TypeScript would
// merge two interfaces silently) fails the build.
// Usage: node scripts/glue.mjs pkg/ruledlab.js (and pkg/cam/ruledlab_cam.js)
import { readFileSync, writeFileSync, existsSync } from 'node:fs';

const file = process.argv[2] ?? 'pkg/ruledlab.js';
let js = readFileSync(file, 'utf8');

const HELPER = `
/** ruledlab: errors of the generated glue, with a code (scripts/glue.mjs). */
function ruledlabGlueError(message) {
    if (message === 'null pointer passed to rust') {
        return Object.assign(new Error('this object has been freed: free() was called on it, or a call took it over'), { code: 'freed' });
    }
    if (/recursive use|while it was borrowed/.test(message)) {
        return Object.assign(new Error(message), { code: 'invalid-state' });
    }
    return Object.assign(new Error(message), { code: 'internal' });
}

/** "null", "an object", "a Float64Array", "a number": what was passed instead. */
function ruledlabDescribe(value) {
    if (value === null || value === undefined) return String(value);
    if (Array.isArray(value)) return 'an array';
    const name = typeof value === 'object' ? (value.constructor?.name === 'Object' ? 'object' : value.constructor?.name ?? 'object') : typeof value;
    return (/^[aeioAEIO]/.test(name) ? 'an ' : 'a ') + name;
}
`;

/** @type {[string | RegExp, string][]} */
const EDITS = [
  [
    // biome-ignore lint/suspicious/noTemplateCurlyInString: the generated glue's text, matched as written
    'throw new Error(`expected instance of ${klass.name}`);',
    // biome-ignore lint/suspicious/noTemplateCurlyInString: the glue's text as it is to become
    "throw Object.assign(new Error(`expected an instance of ${klass.name}, got ${ruledlabDescribe(instance)}`), { code: 'invalid-argument' });",
  ],
  [
    /(__wbg___wbindgen_throw_[0-9a-f]+: function\(arg0, arg1\) \{\n\s*)throw new Error\(getStringFromWasm0\(arg0, arg1\)\);/,
    '$1throw ruledlabGlueError(getStringFromWasm0(arg0, arg1));',
  ],
];

const dtsFile = file.replace(/\.js$/, '.d.ts');
const REFERENCE = '/// <reference lib="esnext.disposable" />\n';
if (existsSync(dtsFile)) {
  let dts = readFileSync(dtsFile, 'utf8');
  // a comment line ` * …` of a derived declaration: Rust's escapes of a string literal
  dts = dts.replace(/^(\s*\*.*)$/gm, (line) =>
    line.replace(/\\u\{([0-9a-f]+)\}|\\(["'\\])/g, (_, hex, ch) =>
      hex ? String.fromCodePoint(parseInt(hex, 16)) : ch,
    ),
  );
  const names = [...dts.matchAll(/^export (?:interface|type|class|enum) (\w+)/gm)].map((m) => m[1]);
  const twice = names.filter((n, i) => names.indexOf(n) !== i);
  if (twice.length) {
    console.error(`glue: declared twice in ${dtsFile}: ${[...new Set(twice)].join(', ')}`);
    process.exit(1);
  }
  if (!dts.startsWith(REFERENCE)) dts = REFERENCE + dts;
  writeFileSync(dtsFile, dts);
}

if (js.includes('function ruledlabGlueError')) {
  console.log(`glue: ${file} already has codes`);
  process.exit(0);
}
// (a module whose functions take no instance of its classes has no class check: the CAM module)
const takesClasses = js.includes('\nfunction _assertClass(');
for (const [from, to] of EDITS) {
  if (!takesClasses && typeof from === 'string' && from.includes('expected instance of')) continue;
  const count = typeof from === 'string' ? js.split(from).length - 1 : (js.match(new RegExp(from, 'g')) ?? []).length;
  if (count !== 1) {
    console.error(
      `glue: expected exactly one match of ${from} in ${file}, found ${count}; has wasm-bindgen's glue changed?`,
    );
    process.exit(1);
  }
  js = typeof from === 'string' ? js.replace(from, to) : js.replace(from, to);
}
js = takesClasses
  ? js.replace(/\nfunction _assertClass\(/, `${HELPER}\nfunction _assertClass(`)
  : js.replace(/\nfunction getStringFromWasm0\(/, `${HELPER}\nfunction getStringFromWasm0(`);
if (!js.includes('function ruledlabGlueError')) {
  console.error('glue: could not place the helper');
  process.exit(1);
}
writeFileSync(file, js);
console.log(`glue: ${file}: codes for wrong classes, freed objects and re-entrant use`);
