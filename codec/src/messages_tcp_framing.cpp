// The length prefix of messages on TCP (server/PROTOCOL.md, "Framing").
#include <cassert>

#include "fw/codec/byte_writer.hpp"
#include "fw/codec/messages.hpp"

namespace fw::codec {

void write_length_prefix(std::size_t message_bytes, std::vector<std::uint8_t>& out) {
  assert(message_bytes >= 1 && message_bytes < (std::size_t{1} << 21));
  ByteWriter(out).varint(static_cast<std::uint32_t>(message_bytes));
}

void write_tcp_frame(std::span<const std::uint8_t> message, std::vector<std::uint8_t>& out) {
  write_length_prefix(message.size(), out);
  out.insert(out.end(), message.begin(), message.end());
}

TcpDeframer::TcpDeframer(std::size_t max_message_bytes) : max_message_bytes_(max_message_bytes) {
  assert(max_message_bytes >= 1 && max_message_bytes < (std::size_t{1} << 21));
}

void TcpDeframer::feed(std::span<const std::uint8_t> bytes) {
  if (error_ != MessageError::ok) return;
  // Drop what was handed out before, so the buffer holds at most one
  // partial message plus this feed.
  if (consumed_ > 0) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(consumed_));
    consumed_ = 0;
  }
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
}

TcpDeframer::Status TcpDeframer::next(std::span<const std::uint8_t>& message) {
  if (error_ != MessageError::ok) return Status::error;
  const std::size_t available = buffer_.size() - consumed_;
  std::size_t length = 0;
  std::size_t prefix = 0;
  for (;;) {
    if (prefix == available) return Status::need_more;
    const std::uint8_t byte = buffer_[consumed_ + prefix];
    length |= static_cast<std::size_t>(byte & 0x7F) << (7 * prefix);
    ++prefix;
    if ((byte & 0x80) == 0) {
      if (prefix > 1 && byte == 0) {  // overlong: one encoding per length
        error_ = MessageError::value_out_of_range;
        return Status::error;
      }
      break;
    }
    if (prefix == kMaxLengthPrefixBytes) {
      error_ = MessageError::too_large;
      return Status::error;
    }
  }
  if (length == 0) {
    error_ = MessageError::empty;
    return Status::error;
  }
  if (length > max_message_bytes_) {
    error_ = MessageError::too_large;
    return Status::error;
  }
  if (available - prefix < length) return Status::need_more;
  message = std::span<const std::uint8_t>(buffer_).subspan(consumed_ + prefix, length);
  consumed_ += prefix + length;
  return Status::message;
}

}  // namespace fw::codec
