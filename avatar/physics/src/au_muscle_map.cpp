#include "fw/physics/au_muscle_map.hpp"

#include <algorithm>
#include <cmath>

namespace fw::physics {
namespace {

// Which muscles each AU recruits (FACS manual; Waters' muscle assignments).
// The weights make each AU alone about as large as the face's geometric AU;
// AU 26 and 27 open the jaw (the digastric) as far as the
// geometric units, 0.2 and 0.42 rad, move the lower lip.
constexpr AuMuscleTerm kAu1[] = {{"frontalis_inner", 1.0f}};
constexpr AuMuscleTerm kAu2[] = {{"frontalis_outer", 1.0f}};
constexpr AuMuscleTerm kAu4[] = {{"corrugator", 1.0f}, {"procerus", 0.6f}};
constexpr AuMuscleTerm kAu5[] = {{"levator_palpebrae", 1.0f}};
constexpr AuMuscleTerm kAu6[] = {{"orbicularis_oculi_orbital", 1.0f}};
constexpr AuMuscleTerm kAu7[] = {{"orbicularis_oculi_palpebral", 1.0f}};
constexpr AuMuscleTerm kAu9[] = {{"levator_labii_alaeque_nasi", 1.0f}, {"nasalis", 0.7f}, {"procerus", 0.5f}};
constexpr AuMuscleTerm kAu10[] = {{"levator_labii_superioris", 1.0f}, {"zygomatic_minor", 0.5f}};
constexpr AuMuscleTerm kAu12[] = {{"zygomatic_major", 1.0f}};
constexpr AuMuscleTerm kAu14[] = {{"buccinator", 1.0f}};
constexpr AuMuscleTerm kAu15[] = {{"depressor_anguli_oris", 1.0f}};
constexpr AuMuscleTerm kAu17[] = {{"mentalis", 1.0f}};
constexpr AuMuscleTerm kAu20[] = {{"risorius", 1.0f}};
constexpr AuMuscleTerm kAu23[] = {{"orbicularis_oris_peripheral", 1.0f}};
constexpr AuMuscleTerm kAu24[] = {{"orbicularis_oris_marginal", 1.0f}, {"masseter", 0.2f}};
constexpr AuMuscleTerm kAu25[] = {{"depressor_labii_inferioris", 1.0f}};
constexpr AuMuscleTerm kAu26[] = {{"digastric", 0.476f}};
constexpr AuMuscleTerm kAu27[] = {{"digastric", 1.0f}, {"orbicularis_oris_peripheral", 0.3f}};

}  // namespace

std::span<const AuMuscleTerm> au_muscle_terms(int au) {
  switch (au) {
    case 1: return kAu1;
    case 2: return kAu2;
    case 4: return kAu4;
    case 5: return kAu5;
    case 6: return kAu6;
    case 7: return kAu7;
    case 9: return kAu9;
    case 10: return kAu10;
    case 12: return kAu12;
    case 14: return kAu14;
    case 15: return kAu15;
    case 17: return kAu17;
    case 20: return kAu20;
    case 23: return kAu23;
    case 24: return kAu24;
    case 25: return kAu25;
    case 26: return kAu26;
    case 27: return kAu27;
    default: return {};
  }
}

std::array<float, kMuscleCount> muscle_activations(const std::array<float, codec::kAuChannelCount>& au) {
  std::array<float, kMuscleCount> activation{};
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const float intensity = std::isfinite(au[c]) ? std::clamp(au[c], 0.0f, 1.0f) : 0.0f;
    if (intensity <= 0.0f) continue;
    const codec::AuChannel channel = codec::kAuChannels[c];
    for (const AuMuscleTerm& term : au_muscle_terms(channel.au)) {
      for (bool left : {true, false}) {
        if (channel.side == codec::AuSide::left && !left) continue;
        if (channel.side == codec::AuSide::right && left) continue;
        const int m = muscle_index(term.muscle, left);
        if (m >= 0) activation[static_cast<std::size_t>(m)] += term.weight * intensity;
      }
    }
  }
  for (float& a : activation) a = std::min(a, 1.0f);
  return activation;
}

}  // namespace fw::physics
