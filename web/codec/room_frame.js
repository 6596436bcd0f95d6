// The byte-aligned messages of a room stream (codec/src/room_frame.cpp,
// FORMAT.md "Room frames", "Resync requests"): a room frame carries one
// frame per avatar of a tick; a resync request asks for key frames.
import { ByteReader } from '../shared/byte_reader.js';
import { ByteWriter } from '../shared/byte_writer.js';
import { FORMAT_VERSION, FrameType, MAX_AVATAR_ID, MAX_FRAME_BYTES, MAX_ROOM_AVATARS, MAX_ROOM_FRAME_BYTES } from './format.js';
import { DecodeError, checkFirstByte } from './decode_error.js';

/** Splits a room frame: { error, entries: [{ avatarId, frame }] } (frames are views into `bytes`). */
export function readRoomFrame(bytes) {
  const entries = [];
  if (bytes.length === 0) return { error: DecodeError.emptyFrame, entries };
  if (bytes.length > MAX_ROOM_FRAME_BYTES) return { error: DecodeError.frameTooLarge, entries };
  const r = new ByteReader(bytes);
  const e = checkFirstByte(r.u8(), FrameType.room);
  if (e !== DecodeError.ok) return { error: e, entries };
  let more = true;
  while (more) {
    if (entries.length === MAX_ROOM_AVATARS) return { error: DecodeError.tooManyAvatars, entries };
    const head = r.varint(4);
    if (r.failed) return { error: DecodeError.truncated, entries };
    const avatarId = Math.floor(head / 2);
    more = head % 2 === 1;
    if (avatarId > MAX_AVATAR_ID) return { error: DecodeError.valueOutOfRange, entries };
    let length = r.remaining;
    if (more) {
      length = r.varint(2);
      if (r.failed) return { error: DecodeError.truncated, entries };
    }
    if (length === 0) return { error: DecodeError.emptyFrame, entries };
    if (length > MAX_FRAME_BYTES) return { error: DecodeError.frameTooLarge, entries };
    if (length > r.remaining) return { error: DecodeError.truncated, entries };
    const frame = r.take(length);
    if (entries.some((x) => x.avatarId === avatarId)) return { error: DecodeError.duplicateAvatar, entries };
    entries.push({ avatarId, frame });
  }
  return { error: DecodeError.ok, entries };
}

/** A resync request asking for key frames of `avatarIds` (at most 64). */
export function writeResyncRequest(avatarIds) {
  if (avatarIds.length > MAX_ROOM_AVATARS) throw new RangeError('at most 64 avatars per resync request');
  const w = new ByteWriter();
  w.u8((FORMAT_VERSION << 4) | FrameType.resyncRequest);
  w.varint(avatarIds.length);
  for (const id of avatarIds) {
    if (!Number.isInteger(id) || id < 0 || id > MAX_AVATAR_ID) throw new RangeError(`bad avatar id ${id}`);
    w.varint(id);
  }
  return w.result();
}

/** Parses a resync request: { error, avatarIds }. */
export function readResyncRequest(bytes) {
  const avatarIds = [];
  if (bytes.length === 0) return { error: DecodeError.emptyFrame, avatarIds };
  const r = new ByteReader(bytes);
  const e = checkFirstByte(r.u8(), FrameType.resyncRequest);
  if (e !== DecodeError.ok) return { error: e, avatarIds };
  const count = r.varint(2);
  if (r.failed) return { error: DecodeError.truncated, avatarIds };
  if (count > MAX_ROOM_AVATARS) return { error: DecodeError.tooManyAvatars, avatarIds };
  for (let i = 0; i < count; i++) {
    const id = r.varint(3);
    if (r.failed) return { error: DecodeError.truncated, avatarIds };
    if (id > MAX_AVATAR_ID) return { error: DecodeError.valueOutOfRange, avatarIds };
    avatarIds.push(id);
  }
  if (r.remaining !== 0) return { error: DecodeError.trailingBytes, avatarIds };
  return { error: DecodeError.ok, avatarIds };
}
