// describe(DecodeError): the sentence a person sees for each error code.
#include "fw/codec/codec.hpp"

namespace fw::codec {

std::string_view describe(DecodeError error) {
  switch (error) {
    case DecodeError::ok: return "no error";
    case DecodeError::empty_frame: return "the frame is empty";
    case DecodeError::unsupported_version:
      return "the face stream is of another format version than this client decodes (version 2 since the "
             "corrective weights): reload the page, or update the client and the server to the same release";
    case DecodeError::unknown_frame_type: return "the frame's type is not one this version knows";
    case DecodeError::wrong_frame_type: return "this kind of frame is not expected here";
    case DecodeError::bad_magic: return "the stream header does not start with FWFP: not a facewire stream";
    case DecodeError::unsupported_schema: return "the stream carries another FaceParams schema; update the client";
    case DecodeError::channel_table_mismatch:
      return "the stream's channel table differs from this client's; update the client";
    case DecodeError::bad_stream_options: return "the stream header has unknown options set or a tick rate of 0";
    case DecodeError::truncated: return "the frame ends before one of its fields";
    case DecodeError::awaiting_key_frame: return "waiting for a key frame; a resync request asks for one";
    case DecodeError::sequence_gap: return "frames were lost; the face holds still until the next key frame";
    case DecodeError::stale_frame: return "a duplicate or late frame was ignored";
    case DecodeError::value_out_of_range: return "the frame decodes to a value outside the allowed range: corrupt";
    case DecodeError::check_failed: return "the frame's check bits do not match: corrupt or cut short";
    case DecodeError::too_many_avatars: return "more avatars than a room may hold";
    case DecodeError::duplicate_avatar: return "the room frame names one avatar twice";
    case DecodeError::frame_too_large: return "the frame is larger than the format allows";
    case DecodeError::trailing_bytes: return "the message has bytes after its end";
  }
  return "unknown error code";
}

}  // namespace fw::codec
