#include "frame_models.hpp"

#include "channel_table.hpp"

namespace fw::codec {

int channel_update_context(const FrameModels& models, std::size_t c, bool active,
                           const std::array<bool, kChannelCount>& updated_now) {
  const int partner = channel_table()[c].partner;
  const int partner_state = partner < 0 ? 0 : (updated_now[static_cast<std::size_t>(partner)] ? 2 : 1);
  return partner_state * 4 + (active ? 2 : 0) + (models.updated_last[c] ? 1 : 0);
}

void encode_damping(RangeEncoder& encoder, std::array<AdaptiveBit, kDampingClasses>& tree, int damping_class) {
  std::size_t node = 1;
  for (int i = kDampingBits - 1; i >= 0; --i) {
    const int bit = (damping_class >> i) & 1;
    encoder.encode(tree[node], bit);
    node = 2 * node + static_cast<std::size_t>(bit);
  }
}

int decode_damping(RangeDecoder& decoder, std::array<AdaptiveBit, kDampingClasses>& tree) {
  std::size_t node = 1;
  for (int i = 0; i < kDampingBits; ++i) node = 2 * node + static_cast<std::size_t>(decoder.decode(tree[node]));
  return static_cast<int>(node - kDampingClasses);
}

}  // namespace fw::codec
