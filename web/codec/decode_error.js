// Why a frame was refused (codec/src/decode_error.cpp). The numbers are
// part of the format and never change (FORMAT.md, "Error codes"): the
// golden vectors name them, and the browser compares with the C++ by them.
import { FORMAT_VERSION, FrameType } from './format.js';

export const DecodeError = Object.freeze({
  ok: 0,
  emptyFrame: 1,
  unsupportedVersion: 2,
  unknownFrameType: 3,
  wrongFrameType: 4,
  badMagic: 5,
  unsupportedSchema: 6,
  channelTableMismatch: 7,
  badStreamOptions: 8,
  truncated: 9,
  awaitingKeyFrame: 10,
  sequenceGap: 11,
  staleFrame: 12,
  valueOutOfRange: 13,
  checkFailed: 14,
  tooManyAvatars: 15,
  duplicateAvatar: 16,
  frameTooLarge: 17,
  trailingBytes: 18,
});
const errorNames = Object.fromEntries(Object.entries(DecodeError).map(([k, v]) => [v, k]));
/** The name of an error code ("checkFailed"), for messages. */
export const errorName = (code) => errorNames[code] ?? `error ${code}`;

/** The verdict on a byte-aligned message's first byte: version, then type. */
export function checkFirstByte(first, expected) {
  if (first >> 4 !== FORMAT_VERSION) return DecodeError.unsupportedVersion;
  if ((first & 0x0f) > FrameType.resyncRequest) return DecodeError.unknownFrameType;
  if ((first & 0x0f) !== expected) return DecodeError.wrongFrameType;
  return DecodeError.ok;
}
