#pragma once
// Field helpers shared by the session-message writer and reader
// (server/PROTOCOL.md, "Encoding"): strings as a varint length and UTF-8
// bytes, 64-bit little-endian numbers, the first byte.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/byte_reader.hpp"
#include "fw/codec/byte_writer.hpp"
#include "fw/codec/messages.hpp"

namespace fw::codec::message_fields {

constexpr std::uint8_t first_byte(MessageType type) {
  return static_cast<std::uint8_t>(kSessionMessageBit | static_cast<std::uint8_t>(type));
}

void write_string(ByteWriter& w, std::string_view text);
void write_u32_le(ByteWriter& w, std::uint32_t value);
void write_u64_le(ByteWriter& w, std::uint64_t value);

/// Whether `text` is UTF-8 without control characters (tab, line feed and
/// carriage return allowed when `allow_layout`: FACS sentences span lines),
/// overlong forms or surrogates.
bool is_clean_text(std::string_view text, bool allow_layout = false);

/// Reads a string of at most `max_bytes` into `out`; sets `error` (only when
/// it is ok) on a cut, an over-long or an unclean string.
void read_string(ByteReader& r, std::size_t max_bytes, std::string& out, MessageError& error,
                 bool allow_layout = false);
/// Reads a language (hello, speaking): at most kMaxLanguageBytes of a-z 0-9 -
/// (bad_text otherwise), empty only when `may_be_empty` (value_out_of_range).
void read_language(ByteReader& r, std::string& out, MessageError& error, bool may_be_empty);
std::uint32_t read_u32_le(ByteReader& r);
std::uint64_t read_u64_le(ByteReader& r);

/// Why a failed reader failed: a number written wrongly (bad_number), or
/// bytes that ran out (truncated).
inline MessageError failure_of(const ByteReader& r) {
  return r.bad_number() ? MessageError::bad_number : MessageError::truncated;
}

/// The first-byte check of every reader.
MessageError check_first_byte(ByteReader& r, std::size_t size, MessageType expected, std::size_t max_bytes);

}  // namespace fw::codec::message_fields
