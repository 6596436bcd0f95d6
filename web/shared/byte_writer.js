// Byte-aligned little-endian fields and LEB128 varints written, as
// codec/include/fw/codec/byte_writer.hpp writes them: the one writer of the
// browser side (resync requests, session messages).

export class ByteWriter {
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
  /** Unsigned LEB128, shortest form. */
  varint(v) {
    while (v >= 0x80) {
      this.u8((v & 0x7f) | 0x80);
      v = Math.floor(v / 128);
    }
    this.u8(v);
  }
  bytes(b) { for (const x of b) this.out.push(x); }
  result() { return Uint8Array.from(this.out); }
}
