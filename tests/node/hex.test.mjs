// The one-file build's wasm travels as hex (scripts/onefile/hex.js): decoded to the very bytes,
// every byte value, either case; text that is not hex is refused, not read as zeros.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hexBytes, hexBytesInJs } from '../../scripts/onefile/hex.js';

test('hex text decodes to its bytes: every byte value, lower and upper case, the decoder in JS and the one used', () => {
  const bytes = new Uint8Array(4096);
  for (let i = 0; i < bytes.length; i++) bytes[i] = (i * 2654435761) >>> 24;
  for (let v = 0; v < 256; v++) bytes[v] = v;
  const text = Buffer.from(bytes).toString('hex');
  assert.deepEqual(hexBytesInJs(text), bytes);
  assert.deepEqual(hexBytesInJs(text.toUpperCase()), bytes);
  assert.deepEqual(hexBytes(text), bytes);
  assert.deepEqual(hexBytesInJs(''), new Uint8Array(0));
});

test('text that is not hex is refused with where it goes wrong', () => {
  assert.throws(() => hexBytesInJs('abc'), /odd length/);
  assert.throws(() => hexBytesInJs('0g'), /not a hex digit at 1/);
  assert.throws(() => hexBytesInJs('zz00'), /not a hex digit at 0/);
  assert.throws(() => hexBytesInJs('00\u00e90'), /not a hex digit at 2/);
});
