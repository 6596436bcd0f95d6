// What a message on the connection is, and what its errors mean
// (server/PROTOCOL.md, "Messages", "Error codes").
#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"

namespace fw::codec {

MessageKind classify(std::span<const std::uint8_t> message) {
  if (message.empty()) return MessageKind::invalid;
  const std::uint8_t first = message[0];
  if (first & kSessionMessageBit) {
    const std::uint8_t type = first & 0x7F;
    const bool known = type >= static_cast<std::uint8_t>(MessageType::hello) &&
                       type <= static_cast<std::uint8_t>(kLastMessageType);
    return known ? MessageKind::session : MessageKind::invalid;
  }
  // A codec message of another format version is still classed by its type,
  // so that its reader refuses it as unsupported_version, whose message
  // tells the person to update, instead of as a message no server sends.
  if ((first >> 4) == 0) return MessageKind::invalid;
  switch (static_cast<FrameType>(first & 0x0F)) {
    case FrameType::stream_header: return MessageKind::stream_header;
    case FrameType::room: return MessageKind::room_frame;
    case FrameType::resync_request: return MessageKind::resync_request;
    default: return MessageKind::invalid;  // bare key/predicted frames travel only inside room frames
  }
}

MessageType session_type(std::span<const std::uint8_t> message) {
  return static_cast<MessageType>(message.empty() ? 0 : (message[0] & 0x7F));
}

std::string_view describe(MessageError error) {
  switch (error) {
    case MessageError::ok: return "no error";
    case MessageError::empty: return "the message is empty";
    case MessageError::not_session_message: return "the first byte does not start a session message";
    case MessageError::unknown_type: return "the message type is unknown to this protocol version";
    case MessageError::wrong_type: return "a message of another type was expected here";
    case MessageError::truncated: return "the message is cut short";
    case MessageError::too_large: return "the message is larger than the protocol allows";
    case MessageError::string_too_long: return "a text field is longer than its limit";
    case MessageError::bad_text:
      return "a text field is not clean UTF-8 (control characters or invalid bytes), or a language is not of "
             "a-z, 0-9 and -";
    case MessageError::value_out_of_range: return "a number lies outside its field's range";
    case MessageError::trailing_bytes: return "bytes follow the message's last field";
    case MessageError::too_many_entries: return "a list holds more entries than allowed";
    case MessageError::unsupported_version: return "another protocol version";
    case MessageError::bad_flags: return "reserved flag bits are set";
    case MessageError::bad_number:
      return "a number is written in more bytes than it needs or than its field allows (each has one encoding)";
  }
  return "unknown message error";
}

}  // namespace fw::codec
