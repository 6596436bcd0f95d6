// The stream header, once per connection (codec/src/stream_header.cpp,
// FORMAT.md "Stream header"): the stream's options, and the channel table
// repeated, so that a decoder refuses a stream it would misread.
import { ByteReader } from '../shared/byte_reader.js';
import { FORMAT_VERSION, FrameType, SCHEMA } from './format.js';
import { DecodeError } from './decode_error.js';
import { CHANNELS, CHANNEL_COUNT } from './channel_table.js';

/** Parses the stream header: { error, options: { lossTolerant, tickRateHz, maxExtrapolationTicks } }. */
export function readStreamHeader(bytes) {
  if (bytes.length === 0) return { error: DecodeError.emptyFrame };
  const r = new ByteReader(bytes);
  const first = r.u8();
  if (first >> 4 !== FORMAT_VERSION) return { error: DecodeError.unsupportedVersion };
  if ((first & 0x0f) > FrameType.resyncRequest) return { error: DecodeError.unknownFrameType };
  if ((first & 0x0f) !== FrameType.streamHeader) return { error: DecodeError.wrongFrameType };
  const magic = [r.u8(), r.u8(), r.u8(), r.u8()];
  if (r.failed) return { error: DecodeError.truncated };
  if (String.fromCharCode(...magic) !== 'FWFP') return { error: DecodeError.badMagic };
  const schema = r.u16();
  const flags = r.u8();
  const tickRateHz = r.u8();
  const maxExtrapolationTicks = r.u8();
  const channels = r.u8();
  if (r.failed) return { error: DecodeError.truncated };
  if (schema !== SCHEMA) return { error: DecodeError.unsupportedSchema };
  if ((flags & ~1) !== 0 || tickRateHz === 0) return { error: DecodeError.badStreamOptions };
  if (channels !== CHANNEL_COUNT) return { error: DecodeError.channelTableMismatch };
  for (const ch of CHANNELS) {
    const group = r.u8();
    const min = r.i16();
    const max = r.i16();
    const step = r.f32();
    const partner = (r.u8() << 24) >> 24;
    const base = (r.u8() << 24) >> 24;
    if (r.failed) return { error: DecodeError.truncated };
    const sameStep = step === ch.step || (Number.isNaN(step) && Number.isNaN(ch.step));
    if (group !== ch.group || min !== ch.min || max !== ch.max || !sameStep || partner !== ch.partner || base !== ch.base)
      return { error: DecodeError.channelTableMismatch };
  }
  if (r.remaining !== 0) return { error: DecodeError.trailingBytes };
  return { error: DecodeError.ok, options: { lossTolerant: (flags & 1) !== 0, tickRateHz, maxExtrapolationTicks } };
}
