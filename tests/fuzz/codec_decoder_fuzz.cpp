// Fuzzes the codec's decoders. The input is read as a stream file (each
// message as a LEB128 length and its bytes, like tests/vectors/codec/*.fwc,
// which seed it): message 0 goes to the stream header reader, the others to
// a RoomDecoder (room frames), a Decoder (anything else) and the resync
// request reader. Whatever the bytes: no crash, no read outside a message,
// known error codes only, and a decoded face always within its ranges. The
// whole input is also decoded as one frame, and read as float faces for an
// encoder whose frames the decoder must reproduce exactly.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "fw/codec/codec.hpp"

namespace {

using namespace fw::codec;

void check(DecodeError e) {
  if (static_cast<int>(e) > static_cast<int>(DecodeError::trailing_bytes)) std::abort();
}

void check_face(const Decoder& d) {
  const QuantisedParams q = d.quantised(0);
  const QuantisedParams later = d.quantised(1000);
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const ChannelInfo& info = channel_table()[c];
    if (q[c] < info.min_q || q[c] > info.max_q || later[c] < info.min_q || later[c] > info.max_q) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  std::vector<std::span<const std::uint8_t>> messages;
  for (std::size_t i = 0; i < size && messages.size() < 512;) {
    std::size_t n = 0;
    int shift = 0;
    while (i < size && shift <= 21) {
      const std::uint8_t b = data[i++];
      n |= static_cast<std::size_t>(b & 0x7F) << shift;
      shift += 7;
      if ((b & 0x80) == 0) break;
    }
    if (n > size - i) n = size - i;
    messages.push_back(input.subspan(i, n));
    i += n;
  }

  StreamOptions options;
  if (!messages.empty()) {
    const DecodeError e = read_stream_header(messages[0], options);
    check(e);
    if (e != DecodeError::ok) options.loss_tolerant = messages[0].size() % 2 == 1;
  }
  Decoder decoder(options);
  RoomDecoder room(options);
  std::vector<std::uint32_t> ids;
  for (std::size_t m = 1; m < messages.size(); ++m) {
    const auto msg = messages[m];
    if (!msg.empty() && (msg[0] & 0x0F) == static_cast<std::uint8_t>(FrameType::room)) {
      const auto result = room.decode(msg);
      check(result.error);
      if (result.avatars.size() > kMaxRoomAvatars) std::abort();
      for (const auto& [id, e] : result.avatars) {
        check(e);
        if (const Decoder* d = room.avatar(id)) check_face(*d);
      }
      if (room.size() > kMaxRoomAvatars) std::abort();
    } else {
      const DecodeError e = decoder.decode(msg);
      check(e);
      if (e == DecodeError::ok && decoder.needs_key_frame()) std::abort();
      check_face(decoder);
    }
    check(read_resync_request(msg, ids));
    if (ids.size() > kMaxRoomAvatars) std::abort();
  }
  Decoder whole(options);
  check(whole.decode(input));
  check_face(whole);

  // The encoder on faces made of the input's bytes: the decoder must show
  // exactly what the encoder reconstructs, tick after tick.
  EncoderOptions eo;
  eo.stream = options;
  eo.stream.tick_rate_hz = 30;
  eo.target_bps = size % 3 == 0 ? 200 : 5000;
  Encoder encoder(eo);
  Decoder mirror(eo.stream);
  std::vector<std::uint8_t> frame;
  std::uint32_t since = 0;
  for (std::size_t at = 0; at + sizeof(float) * kChannelCount <= size && at < 64 * 188; at += 61) {
    FaceParams face;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      float v;
      std::memcpy(&v, data + at + 4 * c, 4);
      set_channel_value(face, c, v);
    }
    if (encoder.encode(face, frame)) {
      if (frame.size() > kMaxFrameBytes || mirror.decode(frame) != DecodeError::ok) std::abort();
      since = 0;
    } else {
      ++since;
    }
    if (mirror.quantised(since) != encoder.reconstruction()) std::abort();
  }
  return 0;
}
