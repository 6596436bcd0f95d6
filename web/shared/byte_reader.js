// Byte-aligned little-endian fields and LEB128 varints, as
// codec/include/fw/codec/byte_reader.hpp reads them: the one reader of the
// browser side, for the codec's stream header, room frames and resync
// requests as for the session messages. Its failure sticks, as the C++
// one's does, so a message is read field by field and checked once at the
// end.

export class ByteReader {
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
  f32() {
    const b = [this.u8(), this.u8(), this.u8(), this.u8()];
    return new DataView(new Uint8Array(b).buffer).getFloat32(0, true);
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
  /** The next `count` bytes as a view (no copy); past the end, none and failed. */
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
