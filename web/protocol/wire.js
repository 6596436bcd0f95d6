// Text on the wire (server/PROTOCOL.md, "Encoding"): strings as a varint
// length and clean UTF-8, written by the shared byte writer
// (web/shared/byte_writer.js) and read by the shared byte reader
// (web/shared/byte_reader.js).

import { ByteWriter } from '../shared/byte_writer.js';

/** The session messages' writer: the shared byte writer and strings. */
export class WireWriter extends ByteWriter {
  string(text) {
    const b = utf8.encode(text);
    this.varint(b.length);
    this.bytes(b);
  }
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
