// Fuzzes the readers of what cluster nodes say to each other over Redis
// (server/rooms/bridge_message.hpp, cluster_limits.hpp): a room's news down,
// a bridging node's requests up, a member record, a room's moods, and the
// limits news. The first input byte picks the reader. Whatever the bytes:
// no crash and no read outside them, and what reads writes back to bytes
// that read again to the same bytes written (one meaning per message).
// What reads is then checked as a node checks what Redis brings
// (cluster_message_check.hpp): no crash, and a message believed once is
// believed again as written, its faces finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "bridge_message.hpp"
#include "cluster_limits.hpp"
#include "cluster_message_check.hpp"
#include "fw/codec/codec.hpp"

namespace {

using namespace fw::server;

template <class Decode>
void round_trip(const bridge::Bytes& written, Decode decode) {
  const auto again = decode(written.data(), written.size());
  if (!again || bridge::encode(*again) != written) std::abort();
}

/// A down message the check let through (its faces clamped): believed
/// again as it is, its faces finite.
void believed_again(const bridge::Down& believed) {
  const auto bytes = bridge::encode(believed);
  auto again = bridge::decode_down(bytes.data(), bytes.size());
  if (!again || cluster_check::refusal_of(*again)) std::abort();
  for (const auto& entry : again->faces)
    for (std::size_t c = 0; c < fw::codec::kChannelCount; ++c)
      if (!std::isfinite(fw::codec::channel_value(entry.face, c))) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t* body = data + 1;
  const std::size_t length = size - 1;
  switch (data[0] % 5) {
    case 0:
      if (auto m = bridge::decode_down(body, length)) {
        round_trip(bridge::encode(*m), bridge::decode_down);
        if (!cluster_check::refusal_of(*m)) believed_again(*m);
      }
      break;
    case 1:
      if (auto m = bridge::decode_up(body, length)) {
        round_trip(bridge::encode(*m), bridge::decode_up);
        (void)cluster_check::refusal_of(*m);
      }
      break;
    case 2:
      if (auto m = bridge::decode_member(body, length)) round_trip(bridge::encode(*m), bridge::decode_member);
      break;
    case 3:
      if (auto m = bridge::decode_state(body, length)) round_trip(bridge::encode(*m), bridge::decode_state);
      break;
    case 4: {
      const std::string_view text(reinterpret_cast<const char*>(body), length);
      if (auto news = decode_limits(text)) {
        const std::string written = encode_limits(*news);
        const auto again = decode_limits(written);
        if (!again || encode_limits(*again) != written) std::abort();
        (void)cluster_check::refusal_of(*news, AbuseLimits{});
      }
      break;
    }
  }
  return 0;
}
