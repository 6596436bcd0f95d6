#include "fw/codec/face_params.hpp"

namespace fw::codec {

static_assert(kAuChannelCount == 29, "11 bilateral AUs with two channels, 7 midline AUs with one");
static_assert(au_channel(12, AuSide::left) == au_channel(12, AuSide::right) - 1);
static_assert(au_channel(26, AuSide::both) >= 0 && au_channel(26, AuSide::left) == -1);
static_assert(au_channel(3, AuSide::both) == -1);

void FaceParams::set_au(int au_number, float intensity) {
  if (is_bilateral(au_number)) {
    for (AuSide side : {AuSide::left, AuSide::right})
      if (const int i = au_channel(au_number, side); i >= 0) au[static_cast<std::size_t>(i)] = intensity;
  } else if (const int i = au_channel(au_number, AuSide::both); i >= 0) {
    au[static_cast<std::size_t>(i)] = intensity;
  }
}

float FaceParams::au_intensity(int au_number, AuSide side) const {
  if (is_bilateral(au_number) && side == AuSide::both)
    return 0.5f * (au_intensity(au_number, AuSide::left) + au_intensity(au_number, AuSide::right));
  if (!is_bilateral(au_number)) side = AuSide::both;
  const int i = au_channel(au_number, side);
  return i >= 0 ? au[static_cast<std::size_t>(i)] : 0.0f;
}

}  // namespace fw::codec
