// Decoders for every avatar of one room stream, at most 64
// (codec/src/room_decoder.cpp): a room frame is split and each avatar's
// frame goes to its own decoder, made at its first frame.
import { MAX_ROOM_AVATARS } from './format.js';
import { DecodeError } from './decode_error.js';
import { Decoder } from './avatar_decoder.js';
import { readRoomFrame } from './room_frame.js';

export class RoomDecoder {
  constructor(options) {
    this.options = options;
    this.decoders = new Map();
  }
  /** Decodes a room frame: { error, avatars: [[avatarId, error], ...] }. */
  decode(bytes) {
    const { error, entries } = readRoomFrame(bytes);
    const result = { error, avatars: [] };
    if (error !== DecodeError.ok) return result;
    for (const { avatarId, frame } of entries) {
      let decoder = this.decoders.get(avatarId);
      if (!decoder) {
        if (this.decoders.size >= MAX_ROOM_AVATARS) {
          result.avatars.push([avatarId, DecodeError.tooManyAvatars]);
          continue;
        }
        decoder = new Decoder(this.options);
        this.decoders.set(avatarId, decoder);
      }
      result.avatars.push([avatarId, decoder.decode(frame)]);
    }
    return result;
  }
  avatar(avatarId) {
    return this.decoders.get(avatarId) ?? null;
  }
  remove(avatarId) {
    this.decoders.delete(avatarId);
  }
  needingKeyFrames() {
    return [...this.decoders].filter(([, d]) => d.needsKeyFrame()).map(([id]) => id);
  }
}
