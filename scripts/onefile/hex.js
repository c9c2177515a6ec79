// The inlined wasm's text: hexadecimal, two letters per byte. Compressed (gzip or brotli, as a
// server or a course system's zip sends the one-file build), hex keeps the bytes' own patterns and
// costs a fifth less than base64, whose 4 letters per 3 bytes break them up (measured on the
// core's wasm: brotli 323 KiB against 408, gzip 428 against 521).

/** The value of each hex digit's character code (lower and upper case); -1 for any other. */
const DIGIT = new Int8Array(128).fill(-1);
for (let d = 0; d < 16; d++) {
  const s = d.toString(16);
  DIGIT[s.charCodeAt(0)] = d;
  DIGIT[s.toUpperCase().charCodeAt(0)] = d;
}

/**
 * The bytes of `text`, two hex digits each (natively where the browser has Uint8Array.fromHex);
 * throws on any other text.
 * @param {string} text
 * @returns {Uint8Array}
 */
export function hexBytes(text) {
  const native = /** @type {{fromHex?: (text: string) => Uint8Array}} */ (/** @type {unknown} */ (Uint8Array));
  if (typeof native.fromHex === 'function') return native.fromHex(text);
  return hexBytesInJs(text);
}

/** hexBytes without the browser's decoder (a few milliseconds for the core's megabyte). @param {string} text */
export function hexBytesInJs(text) {
  if (text.length % 2) throw new Error('hex text of odd length');
  const bytes = new Uint8Array(text.length / 2);
  for (let i = 0; i < bytes.length; i++) {
    const hi = DIGIT[text.charCodeAt(2 * i)] ?? -1;
    const lo = DIGIT[text.charCodeAt(2 * i + 1)] ?? -1;
    if (hi < 0 || lo < 0) throw new Error(`not a hex digit at ${hi < 0 ? 2 * i : 2 * i + 1}`);
    bytes[i] = (hi << 4) | lo;
  }
  return bytes;
}
