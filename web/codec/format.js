// The format's fixed numbers (codec/include/fw/codec/codec.hpp,
// codec/FORMAT.md): version, frame types and size limits. They are part of
// the format and never change within a version.

// Version 2 (FaceParams schema 2) added the six corrective weights; a
// version-1 message is refused (unsupportedVersion).
export const FORMAT_VERSION = 2;
export const SCHEMA = 2;

export const FrameType = Object.freeze({ streamHeader: 0, key: 1, predicted: 2, room: 3, resyncRequest: 4 });

export const MAX_FRAME_BYTES = 1024;
export const MAX_ROOM_AVATARS = 64;
export const MAX_ROOM_FRAME_BYTES = 64 * 1024;
export const MAX_AVATAR_ID = (1 << 21) - 1;
