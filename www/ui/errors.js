// Errors as a reader sees them: in the view's language, built from the error's `code` and
// `details` — the reason and its values, the line and column, a hint — with the field named
// as the page names it ("z-Komponente von e(u): Die Formel endet, wo ein Operand erwartet
// wird (Spalte 3)."). The core's `message` stays the API's English (for the console and for
// programs); texts for every reason of the core's catalogue are in i18n/*/errors.js
// (tests/node/messages.test.mjs checks that each language has them all).

/**
 * @typedef {object} ErrorLike
 * @property {string} [message]
 * @property {string} [code]
 * @property {{option?: string, index?: number, line?: number, column?: number, limit?: number,
 *   reason?: string, args?: Record<string, string | number>, hint?: {reason: string, args: Record<string, string | number>}}} [details]
 * @property {boolean} [localized]   the message is already in the reader's language (errors the page makes itself)
 */

/**
 * The reader's sentence for `error`.
 * @param {unknown} error
 * @param {import('../i18n/index.js').Translator} i18n
 * @param {string} [field]   the name of the field it concerns, as the page shows it (else from details.option)
 */
export function describeError(error, i18n, field) {
  const { t, has } = i18n;
  const e = /** @type {ErrorLike} */ (typeof error === 'object' && error !== null ? error : { message: String(error) });
  if (e.localized) return String(e.message);
  const d = e.details ?? {};
  const reason = d.reason;
  const known = reason && reason !== 'text' && has(`error.${reason}`);
  // a reason the page has no text for (an argument check meant for programmers): what kind of problem it is
  const text = known
    ? t(`error.${reason}`, values(d.args, i18n))
    : t(has(`error.code.${e.code}`) ? `error.code.${e.code}` : 'error.code.unknown');
  const name = field ?? (d.option ? optionName(d.option, i18n) : '');
  const at =
    d.line && d.column
      ? t('error.atLineColumn', { line: d.line, column: d.column })
      : d.line
        ? t('error.atLine', { line: d.line })
        : d.column
          ? t('error.atColumn', { column: d.column })
          : '';
  const hint = d.hint && has(`error.${d.hint.reason}`) ? t(`error.${d.hint.reason}`, values(d.hint.args, i18n)) : '';
  const sentence = `${text}${at ? ` ${at}` : ''}${hint ? t('error.hintJoin', { hint }) : ''}`;
  return `${upper(name ? t('error.field', { field: name, text: sentence }) : sentence)}${/[.!?]$/.test(sentence) ? '' : '.'}`;
}

/** The page's name of an option the core names ("csv", "u", "parameters"), or the option itself. */
function optionName(/** @type {string} */ option, /** @type {import('../i18n/index.js').Translator} */ { t, has }) {
  return has(`error.option.${option}`) ? t(`error.option.${option}`) : option;
}

/**
 * The values of a reason for the reader: numbers in the language's form (a decimal comma in
 * German, at most six significant digits), the thing counted (`what`) in its words, a value
 * whose name ends in "Reason" (a hint inside the sentence) replaced by its text.
 * @param {Record<string, string | number> | undefined} args
 * @param {import('../i18n/index.js').Translator} i18n
 * @returns {Record<string, string>}
 */
function values(args, { t, has, lang }) {
  /** @type {Record<string, string>} */
  const out = {};
  for (const [key, value] of Object.entries(args ?? {})) {
    if (key.endsWith('Reason'))
      out[key.slice(0, -'Reason'.length)] = has(`error.${value}`) ? t(`error.${value}`) : String(value);
    else if (typeof value === 'number') out[key] = number(value, lang);
    else if (key === 'what') out[key] = has(`error.what.${value}`) ? t(`error.what.${value}`) : value;
    else out[key] = value;
  }
  for (const [key, value] of Object.entries(args ?? {}))
    if (key.endsWith('Reason')) out[key.slice(0, -'Reason'.length)] ??= String(value);
  return out;
}

/** A number for a message: integers as they are, others to six significant digits. */
export function number(/** @type {number} */ x, /** @type {string} */ lang) {
  if (Number.isNaN(x)) return 'NaN';
  if (!Number.isFinite(x)) return x > 0 ? '∞' : '−∞';
  if (Number.isInteger(x) && Math.abs(x) < 1e15) return String(x).replace('-', '−');
  const a = Math.abs(x);
  const text =
    a !== 0 && (a >= 1e15 || a < 1e-4) ? x.toExponential(3).replace(/\.?0+e/, 'e') : String(Number(x.toPrecision(6)));
  return (lang === 'de' ? text.replace('.', ',') : text).replace('-', '−');
}

/** The sentence with its first letter a capital, when it starts with a word ("ruling 3 …"), not a symbol ("e(u) …"). */
function upper(/** @type {string} */ s) {
  return /^\p{Ll}+[\s,]/u.test(s) ? s.charAt(0).toUpperCase() + s.slice(1) : s;
}

/**
 * Why ruledlab could not start, in the reader's language: no WebGL2, no WebAssembly (or none
 * with SIMD), a file that did not load, or else in general. The browser's own message is for
 * `technical` (shown apart, in English, for whoever reports the problem).
 * @param {unknown} error
 * @param {import('../i18n/index.js').Translator} i18n
 * @returns {{text: string, technical: string}}
 */
export function startFailure(error, { t }) {
  const e = /** @type {any} */ (error);
  const technical = String(e?.message ?? e);
  const key =
    e?.code === 'no-webgl2'
      ? 'boot.noWebgl2'
      : // a page whose Content-Security-Policy forbids compiling WebAssembly (not the browser's fault)
        /Content.Security.Policy|wasm-unsafe-eval|unsafe-eval/i.test(technical)
        ? 'boot.cspWasm'
        : typeof WebAssembly === 'undefined' ||
            e instanceof WebAssembly.CompileError ||
            e instanceof WebAssembly.LinkError
          ? 'boot.noWasm'
          : /fetch|import|load|network|MIME/i.test(technical)
            ? 'boot.load'
            : 'boot.failed';
  return { text: t(key), technical };
}
