// The FaceParams stream decoder for the browser: a port of the C++ decoder
// (codec/src, one module per source file it ports) written from
// codec/FORMAT.md. It must decode the golden vectors (tests/vectors/codec)
// to exactly the same integers; node's test runner checks that
// (tests/codec/js). This is its public entry, as codec/include/fw/codec/codec.hpp
// is the C++'s.
//
// Usage:
//   const header = readStreamHeader(bytes);            // once per connection
//   const room = new RoomDecoder(header.options);
//   const result = room.decode(roomFrameBytes);          // every room frame
//   const face = room.avatar(id).face(ticksSinceFrame);  // FaceParams-like object
//   if (room.needingKeyFrames().length) send(writeResyncRequest(room.needingKeyFrames()));

export { FORMAT_VERSION, SCHEMA, FrameType, MAX_FRAME_BYTES, MAX_ROOM_AVATARS, MAX_ROOM_FRAME_BYTES, MAX_AVATAR_ID } from './format.js';
export { DecodeError, errorName } from './decode_error.js';
export { CHANNELS, CHANNEL_COUNT } from './channel_table.js';
export { dequantise } from './quantiser.js';
export { Decoder } from './avatar_decoder.js';
export { readStreamHeader } from './stream_header.js';
export { readRoomFrame, readResyncRequest, writeResyncRequest } from './room_frame.js';
export { RoomDecoder } from './room_decoder.js';
