// Decodes the PNG screenshots Chromium writes (8-bit RGB or RGBA, not interlaced) so page
// tests can look at real pixels without extra dependencies.
import { inflateSync } from 'node:zlib';

/** @typedef {{width: number, height: number, channels: number, data: Uint8Array}} Image */

/** @param {Buffer} buffer @returns {Image} */
export function decodePng(buffer) {
  const sig = '89504e470d0a1a0a';
  if (buffer.subarray(0, 8).toString('hex') !== sig) throw new Error('not a PNG');
  let pos = 8;
  let width = 0,
    height = 0,
    channels = 0;
  const idat = [];
  while (pos < buffer.length) {
    const len = buffer.readUInt32BE(pos);
    const type = buffer.toString('ascii', pos + 4, pos + 8);
    const body = buffer.subarray(pos + 8, pos + 8 + len);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      const [depth, color, , , interlace] = body.subarray(8, 13);
      if (depth !== 8 || interlace !== 0 || (color !== 2 && color !== 6)) {
        throw new Error(`unsupported PNG: depth ${depth}, color type ${color}, interlace ${interlace}`);
      }
      channels = color === 6 ? 4 : 3;
    } else if (type === 'IDAT') idat.push(body);
    else if (type === 'IEND') break;
    pos += 12 + len;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const data = new Uint8Array(height * stride);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? data[y * stride + x - channels] : 0;
      const b = y > 0 ? data[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? data[(y - 1) * stride + x - channels] : 0;
      const predictor = [0, a, b, (a + b) >> 1, paeth(a, b, c)][filter];
      data[y * stride + x] = (line[x] + predictor) & 255;
    }
  }
  return { width, height, channels, data };
}

/** @param {number} a @param {number} b @param {number} c */
function paeth(a, b, c) {
  const p = a + b - c;
  const pa = Math.abs(p - a),
    pb = Math.abs(p - b),
    pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/**
 * Number of pixels whose colour differs from `rgb` by more than `tolerance` in any channel.
 * @param {Image} image @param {ArrayLike<number>} rgb @param {number} [tolerance]
 */
export function countDifferent(image, rgb, tolerance = 12) {
  const { data, channels } = image;
  let n = 0;
  for (let i = 0; i < data.length; i += channels) {
    if (
      Math.abs(data[i] - rgb[0]) > tolerance ||
      Math.abs(data[i + 1] - rgb[1]) > tolerance ||
      Math.abs(data[i + 2] - rgb[2]) > tolerance
    )
      n++;
  }
  return n;
}

/**
 * Number of pixels that differ between two images of the same size.
 * @param {Image} a @param {Image} b @param {number} [tolerance]
 */
export function countChanged(a, b, tolerance = 12) {
  if (a.width !== b.width || a.height !== b.height) return a.width * a.height;
  let n = 0;
  for (let i = 0; i < a.data.length; i += a.channels) {
    for (let k = 0; k < 3; k++) {
      if (Math.abs(a.data[i + k] - b.data[i + k]) > tolerance) {
        n++;
        break;
      }
    }
  }
  return n;
}
