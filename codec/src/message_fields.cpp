#include "message_fields.hpp"

namespace fw::codec::message_fields {

void write_string(ByteWriter& w, std::string_view text) {
  w.varint(static_cast<std::uint32_t>(text.size()));
  w.bytes({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void write_u32_le(ByteWriter& w, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) w.u8(static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF));
}

void write_u64_le(ByteWriter& w, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) w.u8(static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF));
}

bool is_clean_text(std::string_view text, bool allow_layout) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<std::uint8_t>(text[i]);
    if (c < 0x80) {
      if ((c < 0x20 && !(allow_layout && (c == '\t' || c == '\n' || c == '\r'))) || c == 0x7F) return false;
      ++i;
      continue;
    }
    std::size_t length = 0;
    std::uint32_t code = 0;
    if ((c & 0xE0) == 0xC0) length = 2, code = c & 0x1Fu;
    else if ((c & 0xF0) == 0xE0) length = 3, code = c & 0x0Fu;
    else if ((c & 0xF8) == 0xF0) length = 4, code = c & 0x07u;
    else return false;
    if (i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k) {
      const auto cc = static_cast<std::uint8_t>(text[i + k]);
      if ((cc & 0xC0) != 0x80) return false;
      code = (code << 6) | (cc & 0x3Fu);
    }
    static constexpr std::uint32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kSmallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    if (code >= 0x80 && code < 0xA0) return false;  // C1 controls
    i += length;
  }
  return true;
}

void read_string(ByteReader& r, std::size_t max_bytes, std::string& out, MessageError& error, bool allow_layout) {
  out.clear();
  const std::uint32_t length = r.varint(3);
  if (r.failed()) {
    if (error == MessageError::ok) error = failure_of(r);
    return;
  }
  if (length > max_bytes) {
    if (error == MessageError::ok) error = MessageError::string_too_long;
    return;
  }
  const auto bytes = r.bytes(length);
  if (r.failed()) {
    if (error == MessageError::ok) error = MessageError::truncated;
    return;
  }
  out.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (!is_clean_text(out, allow_layout) && error == MessageError::ok) error = MessageError::bad_text;
}

void read_language(ByteReader& r, std::string& out, MessageError& error, bool may_be_empty) {
  const MessageError before = error;
  read_string(r, kMaxLanguageBytes, out, error);
  if (before != MessageError::ok || error != MessageError::ok || r.failed()) return;
  if (out.empty()) {
    if (!may_be_empty) error = MessageError::value_out_of_range;
  } else if (!is_language_code(out)) {
    error = MessageError::bad_text;
  }
}

std::uint32_t read_u32_le(ByteReader& r) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(r.u8()) << (8 * i);
  return value;
}

std::uint64_t read_u64_le(ByteReader& r) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value |= static_cast<std::uint64_t>(r.u8()) << (8 * i);
  return value;
}

MessageError check_first_byte(ByteReader& r, std::size_t size, MessageType expected, std::size_t max_bytes) {
  if (size == 0) return MessageError::empty;
  if (size > max_bytes) return MessageError::too_large;
  const std::uint8_t first = r.u8();
  if ((first & kSessionMessageBit) == 0) return MessageError::not_session_message;
  const std::uint8_t type = first & 0x7F;
  if (type < static_cast<std::uint8_t>(MessageType::hello) || type > static_cast<std::uint8_t>(kLastMessageType))
    return MessageError::unknown_type;
  if (type != static_cast<std::uint8_t>(expected)) return MessageError::wrong_type;
  return MessageError::ok;
}

}  // namespace fw::codec::message_fields

namespace fw::codec {

bool is_language_code(std::string_view code) {
  if (code.empty() || code.size() > kMaxLanguageBytes) return false;
  for (const char c : code)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-')) return false;
  return true;
}

}  // namespace fw::codec
