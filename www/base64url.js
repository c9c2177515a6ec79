// base64url without padding (RFC 4648, section 5): bytes as the letters a link carries unescaped.
// The reader's edit (edit/input.js: its doubles' bytes) and an exercise of one's own (task/format.js:
// its JSON's UTF-8 bytes) travel in links this way.

const ALPHABET = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';
/** @type {Record<string, number>} */
const VALUE = Object.fromEntries([...ALPHABET].map((c, i) => [c, i]));

/** base64url (no padding) of bytes. */
export function toBase64url(/** @type {Uint8Array} */ bytes) {
  let out = '';
  for (let i = 0; i < bytes.length; i += 3) {
    const [a, b = 0, c = 0] = [bytes[i], bytes[i + 1], bytes[i + 2]];
    const n = (a << 16) | (b << 8) | c;
    const chars = i + 2 < bytes.length ? 4 : i + 1 < bytes.length ? 3 : 2;
    for (let k = 0; k < chars; k++) out += ALPHABET[(n >> (18 - 6 * k)) & 63];
  }
  return out;
}

/** The bytes of base64url text, or null when it is not that. */
export function fromBase64url(/** @type {string} */ text) {
  if (text.length % 4 === 1) return null;
  const bytes = new Uint8Array(Math.floor((text.length * 3) / 4));
  let k = 0;
  for (let i = 0; i < text.length; i += 4) {
    let n = 0;
    const chunk = text.slice(i, i + 4);
    for (let j = 0; j < 4; j++) {
      const v = j < chunk.length ? VALUE[chunk[j]] : 0;
      if (v === undefined) return null;
      n = (n << 6) | v;
    }
    for (let j = 0; j < chunk.length - 1; j++) bytes[k++] = (n >> (16 - 8 * j)) & 255;
  }
  return bytes;
}
