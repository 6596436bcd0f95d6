// Bytes on the wire (server/PROTOCOL.md, "Encoding"): a reader whose failure
// sticks, as the C++ ByteReader's does, so a message is read field by field
// and checked once at the end; a growing writer; strings as a varint length
// and clean UTF-8.

export class WireReader {
  constructor(bytes) {
    this.bytes = bytes;
    this.position = 0;
    this.failed = false;
    this.badNumber = false;  // failed on a number written wrongly, not on bytes running out
  }
  get remaining() { return this.bytes.length - this.position; }
  u8() {
    if (this.position >= this.bytes.length) {
      this.failed = true;
      return 0;
    }
    return this.bytes[this.position++];
  }
  u16() { return this.u8() | (this.u8() << 8); }
  i16() {
    const v = this.u16();
    return v >= 0x8000 ? v - 0x10000 : v;
  }
  u32() {
    let v = 0;
    for (let i = 0; i < 4; ++i) v += this.u8() * 2 ** (8 * i);
    return v;
  }
  /** A u64 as a BigInt: clocks in microseconds are Numbers in practice, but a
   * reader must not round what it was sent. */
  u64() {
    const lo = this.u32();
    return BigInt(lo) + (BigInt(this.u32()) << 32n);
  }
  /** Unsigned LEB128 of at most `maxBytes`; overlong forms and values past 32 bits fail. */
  varint(maxBytes) {
    let value = 0;
    for (let i = 0; i < maxBytes && i < 5; ++i) {
      const byte = this.u8();
      if (this.failed) return 0;
      const payload = byte & 0x7f;
      if (i === 4 && payload > 0x0f) break;
      value += payload * 2 ** (7 * i);
      if ((byte & 0x80) === 0) {
        if (i > 0 && byte === 0) break;  // overlong: every value has one encoding
        return value;
      }
    }
    this.failed = true;
    this.badNumber = true;
    return 0;
  }
  take(count) {
    if (count > this.remaining) {
      this.failed = true;
      this.position = this.bytes.length;
      return new Uint8Array(0);
    }
    const view = this.bytes.subarray(this.position, this.position + count);
    this.position += count;
    return view;
  }
}

export class WireWriter {
  constructor() {
    this.out = [];
  }
  u8(v) { this.out.push(v & 0xff); }
  u16(v) {
    this.u8(v);
    this.u8(v >> 8);
  }
  i16(v) { this.u16(v < 0 ? v + 0x10000 : v); }
  u32(v) {
    for (let i = 0; i < 4; ++i) this.u8(Math.floor(v / 2 ** (8 * i)));
  }
  /** A BigInt or a whole Number. */
  u64(v) {
    const big = BigInt(v);
    this.u32(Number(big & 0xffffffffn));
    this.u32(Number(big >> 32n));
  }
  varint(v) {
    while (v >= 0x80) {
      this.u8((v & 0x7f) | 0x80);
      v = Math.floor(v / 128);
    }
    this.u8(v);
  }
  bytes(b) { for (const x of b) this.out.push(x); }
  string(text) {
    const b = utf8.encode(text);
    this.varint(b.length);
    this.bytes(b);
  }
  result() { return Uint8Array.from(this.out); }
}

const utf8 = new TextEncoder();
const utf8Decoder = new TextDecoder('utf-8', { fatal: false });

/** Whether `bytes` are UTF-8 without control characters (tab, LF, CR when
 * `allowLayout`: FACS sentences span lines), overlong forms or surrogates. */
export function isCleanText(bytes, allowLayout = false) {
  const smallest = [0, 0, 0x80, 0x800, 0x10000];
  let i = 0;
  while (i < bytes.length) {
    const c = bytes[i];
    if (c < 0x80) {
      if ((c < 0x20 && !(allowLayout && (c === 9 || c === 10 || c === 13))) || c === 0x7f) return false;
      ++i;
      continue;
    }
    let length = 0;
    let code = 0;
    if ((c & 0xe0) === 0xc0) [length, code] = [2, c & 0x1f];
    else if ((c & 0xf0) === 0xe0) [length, code] = [3, c & 0x0f];
    else if ((c & 0xf8) === 0xf0) [length, code] = [4, c & 0x07];
    else return false;
    if (i + length > bytes.length) return false;
    for (let k = 1; k < length; ++k) {
      const cc = bytes[i + k];
      if ((cc & 0xc0) !== 0x80) return false;
      code = code * 64 + (cc & 0x3f);
    }
    if (code < smallest[length] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return false;
    if (code >= 0x80 && code < 0xa0) return false;  // C1 controls
    i += length;
  }
  return true;
}

/** The byte length of `text` in UTF-8 (limits count bytes, not characters). */
export const utf8Length = (text) => utf8.encode(text).length;
export const decodeUtf8 = (bytes) => utf8Decoder.decode(bytes);
