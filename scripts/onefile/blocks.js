// The one-file page carries its big texts — the two wasm modules (hex) and the worker's source —
// beside its script, in data blocks (<script type="text/plain" id="…">) that the browser does not
// parse as JavaScript: read when needed (the CAM module only when asked for), they keep the
// script small, so evaluating it is no longer one long task. The script holds a placeholder for
// each ("@ruledlab-block:<id>"); the embed script (dist/ruledlab-embed.js), which must work
// alone, holds the texts themselves in their place — the same script otherwise, and the one-file
// page hands it out as such (standalone()).

/** The data blocks, by the name the build's virtual module gives their text. */
export const BLOCKS = /** @type {const} */ ({
  WASM: 'ruledlab-wasm',
  CAM_WASM: 'ruledlab-cam-wasm',
  WORKER: 'ruledlab-worker',
});

/** The placeholder of block `id` in the page's script. */
export const placeholder = (/** @type {string} */ id) => `@ruledlab-block:${id}`;

/**
 * The blocks of this page, taken while its script starts (the page then replaces its body).
 * @type {Map<string, HTMLElement>}
 */
const found = new Map(
  typeof document === 'undefined'
    ? []
    : Object.values(BLOCKS).flatMap((id) => {
        const element = document.getElementById(id);
        return element ? [/** @type {[string, HTMLElement]} */ ([id, element])] : [];
      }),
);

/**
 * The text `value` stands for: itself (the embed script carries its texts), or the text of the
 * data block its placeholder names (the one-file page).
 * @param {string} value
 */
export function blockText(value) {
  const prefix = placeholder('');
  if (!value.startsWith(prefix)) return value;
  const element = found.get(value.slice(prefix.length));
  if (!element) throw new Error(`the one-file page lacks its data block "${value.slice(prefix.length)}"`);
  return element.textContent ?? '';
}

/** The blocks as written, for the page's copies of itself (Share → one file). */
export function blocksHtml() {
  return [...found.values()].map((e) => e.outerHTML).join('\n');
}

/**
 * The embed script that works alone, from the page's own script `source`: each placeholder
 * replaced by its block's text, as the build made dist/ruledlab-embed.js.
 * @param {string} source
 */
export function standalone(source) {
  let out = source;
  for (const id of Object.values(BLOCKS))
    if (found.has(id))
      out = out.replaceAll(JSON.stringify(placeholder(id)), JSON.stringify(blockText(placeholder(id))));
  return out;
}
