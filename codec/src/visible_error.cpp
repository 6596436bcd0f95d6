// default_visible_error(): how much error each channel may show before a
// viewer sees it (FORMAT.md, "Encoder"). Encoder policy only: the format
// does not depend on these numbers.
#include <numbers>

#include "fw/codec/codec.hpp"

namespace fw::codec {
namespace {

constexpr float kVisibleMm = 0.35f;  // vertex error a viewer just misses
constexpr float kVisibleGazeRad = static_cast<float>(0.4 * std::numbers::pi / 180.0);
constexpr float kHeadReachMm = 126.0f;  // neck pivot to the farthest vertex: 2 units of 63 mm
constexpr float kLidTravelMm = 10.0f;
constexpr float kVisibleColour = 1.0f / 32.0f;
// Largest skin motion of one corrective component at weight 1: the physics
// residual the components stand for is 0.4 mm RMS and 3.4 mm at its worst
// vertex, and the first component carries most of it.
constexpr float kCorrectiveReachMm = 3.4f;

// Largest displacement (mm, intensity 1) of each AU's motion, apparent
// texture motion included, from avatar/model/EXPRESSIONS.md (0.1 unit =
// 6.3 mm) with about 20 % margin; AU 26 and 27 turn the jaw 0.2 and 0.42 rad
// about a hinge some 1.5 units from the chin.
float au_reach_mm(int au) {
  switch (au) {
    case 1: return 10.0f;
    case 2: return 9.0f;
    case 4: return 8.0f;
    case 5: return 3.0f;
    case 6: return 5.5f;
    case 7: return 3.0f;
    case 9: return 5.0f;
    case 10: return 5.5f;
    case 12: return 9.5f;
    case 14: return 5.0f;
    case 15: return 6.0f;
    case 17: return 4.0f;
    case 20: return 6.0f;
    case 23: return 3.0f;
    case 24: return 2.0f;
    case 25: return 5.0f;
    case 26: return 24.0f;
    case 27: return 50.0f;
    default: return 50.0f;  // an AU not in the table: assume the largest motion
  }
}

}  // namespace

std::array<float, kChannelCount> default_visible_error() {
  std::array<float, kChannelCount> e{};
  for (std::size_t c = 0; c < kAuChannelCount; ++c) e[c] = kVisibleMm / au_reach_mm(kAuChannels[c].au);
  std::size_t c = kAuChannelCount;
  for (int i = 0; i < 3; ++i) e[c++] = kVisibleMm / kHeadReachMm;  // rad
  for (int i = 0; i < 3; ++i) e[c++] = kVisibleMm;                 // mm
  for (int i = 0; i < 4; ++i) e[c++] = kVisibleGazeRad;            // each eye's yaw and pitch together
  for (int i = 0; i < 2; ++i) e[c++] = kVisibleMm / kLidTravelMm;
  for (std::size_t i = 0; i < kColourRegionCount + 1; ++i) e[c++] = kVisibleColour;
  while (c < kChannelCount) e[c++] = kVisibleMm / kCorrectiveReachMm;
  return e;
}

}  // namespace fw::codec
