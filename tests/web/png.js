// Reads the PNGs m3055 writes (8-bit RGB or RGBA, non-interlaced, any row
// filter) into { width, height, channels, pixels }: enough to compare the
// page's display with `m3055 render`'s level by level, without a dependency.
'use strict';
const zlib = require('zlib');

function paeth(a, b, c) {
  const p = a + b - c;
  const pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

function decodePng(buffer) {
  if (buffer.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let offset = 8, width = 0, height = 0, channels = 0;
  const idat = [];
  while (offset < buffer.length) {
    const length = buffer.readUInt32BE(offset);
    const type = buffer.toString('ascii', offset + 4, offset + 8);
    const data = buffer.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      const depth = data[8], colour = data[9], interlace = data[12];
      if (depth !== 8 || (colour !== 2 && colour !== 6) || interlace !== 0) throw new Error('unsupported PNG');
      channels = colour === 2 ? 3 : 4;
    } else if (type === 'IDAT') {
      idat.push(data);
    }
    offset += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const row = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? pixels[y * stride + x - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[(y - 1) * stride + x - channels] : 0;
      const v = row[x];
      let out;
      switch (filter) {
        case 0: out = v; break;
        case 1: out = v + a; break;
        case 2: out = v + b; break;
        case 3: out = v + ((a + b) >> 1); break;
        case 4: out = v + paeth(a, b, c); break;
        default: throw new Error('bad PNG filter ' + filter);
      }
      pixels[y * stride + x] = out & 0xff;
    }
  }
  return { width, height, channels, pixels };
}

// Pixels whose level (of 2^bits - 1) differs in any channel, and the largest
// difference in levels, and the pixels more than one level off. The display
// writes level L as round(L * 255 / (2^bits - 1)).
// With `mask` (1 a pixel counted, 0 one left out) only the masked pixels count.
function compareLevels(a, b, bits, mask = null) {
  if (a.width !== b.width || a.height !== b.height) return { sizeDiffers: true, differing: a.width * a.height, maxLevels: Infinity, beyondOne: a.width * a.height };
  const top = (1 << bits) - 1;
  const level = (v) => Math.round((v * top) / 255);
  let differing = 0, maxLevels = 0, counted = 0, beyondOne = 0;
  for (let i = 0; i < a.width * a.height; ++i) {
    if (mask && !mask[i]) continue;
    ++counted;
    let pixelMax = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(level(a.pixels[i * a.channels + c]) - level(b.pixels[i * b.channels + c]));
      pixelMax = Math.max(pixelMax, d);
    }
    if (pixelMax > 0) ++differing;
    if (pixelMax > 1) ++beyondOne;
    maxLevels = Math.max(maxLevels, pixelMax);
  }
  return { sizeDiffers: false, differing, maxLevels, beyondOne, pixels: counted };
}

module.exports = { decodePng, compareLevels };
