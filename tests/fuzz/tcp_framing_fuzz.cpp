// Fuzzes the TCP framing (codec/messages.hpp: TcpDeframer, which the
// server's TCP sessions and the native client's socket read through;
// PROTOCOL.md section 2). The input's first byte picks the limit (the
// server's upstream one or the client's downstream one), the next four the
// sizes of the pieces the stream arrives in, cycled as a socket might
// deliver them; the rest is the stream. Whatever the bytes and however
// they are cut, the deframer must return the messages, and the error or the
// wait for more, that the protocol's own wording gives for the whole
// stream; it must never hold more than one unfinished message once
// drained; and the messages framed again must be the bytes it consumed
// (one spelling per length). Seeded with framed conversations of real
// messages (corpus/tcp_framing_fuzz, written by fuzz_make_seeds).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "fw/codec/messages.hpp"
#include "seed_check.hpp"
#include "tcp_framing_fuzz_input.hpp"

namespace {

using namespace fw::codec;
using Bytes = std::span<const std::uint8_t>;

/// What the protocol says of a whole stream: its messages, then an error or
/// a wait for more with `left` bytes of an unfinished message.
struct Reading {
  std::vector<Bytes> messages;
  MessageError error = MessageError::ok;
  std::size_t left = 0;
};

/// PROTOCOL.md section 2, as written there: a length of 1 .. 3 bytes of
/// unsigned LEB128, neither zero nor overlong nor over the limit, then that
/// many bytes.
Reading read_as_specified(Bytes stream, std::size_t limit) {
  Reading reading;
  std::size_t at = 0;
  while (true) {
    std::size_t length = 0, prefix = 0;
    bool complete = false;
    while (at + prefix < stream.size() && prefix < kMaxLengthPrefixBytes) {
      const std::uint8_t byte = stream[at + prefix];
      length |= static_cast<std::size_t>(byte & 0x7F) << (7 * prefix);
      ++prefix;
      if ((byte & 0x80) == 0) {
        if (prefix > 1 && byte == 0) reading.error = MessageError::value_out_of_range;
        complete = true;
        break;
      }
    }
    if (reading.error != MessageError::ok) return reading;
    if (!complete) {
      if (prefix == kMaxLengthPrefixBytes) reading.error = MessageError::too_large;  // a fourth byte would follow
      else reading.left = stream.size() - at;
      return reading;
    }
    if (length == 0) reading.error = MessageError::empty;
    else if (length > limit) reading.error = MessageError::too_large;
    if (reading.error != MessageError::ok) return reading;
    if (stream.size() - at - prefix < length) {
      reading.left = stream.size() - at;
      return reading;
    }
    reading.messages.push_back(stream.subspan(at + prefix, length));
    at += prefix + length;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto input = fw::fuzz::TcpFramingInput::parse(Bytes(data, size));
  if (!input) return 0;
  const Reading expected = read_as_specified(input->stream, input->limit);

  TcpDeframer deframer(input->limit);
  std::vector<std::vector<std::uint8_t>> messages;
  TcpDeframer::Status status = TcpDeframer::Status::need_more;
  std::size_t at = 0;
  for (std::size_t piece = 0; at < input->stream.size() && status != TcpDeframer::Status::error; ++piece) {
    const std::size_t n = std::min(input->piece_bytes[piece % input->piece_bytes.size()], input->stream.size() - at);
    deframer.feed(input->stream.subspan(at, n));
    at += n;
    Bytes message;
    while ((status = deframer.next(message)) == TcpDeframer::Status::message) {
      if (message.empty() || message.size() > input->limit) std::abort();
      messages.emplace_back(message.begin(), message.end());
    }
    // Drained: at most one unfinished message (its length and part of it).
    if (status == TcpDeframer::Status::need_more && deframer.buffered() >= kMaxLengthPrefixBytes + input->limit)
      std::abort();
  }

  if (messages.size() != expected.messages.size()) std::abort();
  std::vector<std::uint8_t> framed;
  for (std::size_t i = 0; i < messages.size(); ++i) {
    if (!std::equal(messages[i].begin(), messages[i].end(), expected.messages[i].begin(), expected.messages[i].end()))
      std::abort();
    write_tcp_frame(messages[i], framed);
  }
  if (!std::equal(framed.begin(), framed.end(), input->stream.begin(), input->stream.begin() + framed.size()))
    std::abort();
  if (expected.error != MessageError::ok) {
    if (status != TcpDeframer::Status::error || deframer.error() != expected.error) std::abort();
    fw::fuzz::seed_refused(describe(expected.error));
    return 0;
  }
  if (status == TcpDeframer::Status::error || deframer.buffered() != expected.left) std::abort();
  if (expected.left != 0) fw::fuzz::seed_refused("the stream ends inside a message");
  return 0;
}
