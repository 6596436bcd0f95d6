#include "fw/speech/coarticulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fw::speech {
namespace {

constexpr std::array<Dominance, kVisemeCount> kDominance = {{
    {1.5f, 15.0f, 15.0f},   // rest: a pause closes the mouth
    {8.0f, 50.0f, 80.0f},   // bilabial: the lips close, and part quickly
    {6.0f, 50.0f, 80.0f},   // labiodental
    {1.5f, 30.0f, 30.0f},   // dental
    {1.0f, 30.0f, 30.0f},   // alveolar
    {1.5f, 30.0f, 30.0f},   // postalveolar: lip protrusion is a real target
    {1.0f, 30.0f, 30.0f},   // velar
    {0.3f, 30.0f, 30.0f},   // glottal: the neighbouring vowel's mouth
    {1.0f, 30.0f, 30.0f},   // rhotic
    {1.0f, 25.0f, 30.0f},   // open vowel: vowels carry across consonants (Ohman, JASA 39, 1966)
    {1.0f, 25.0f, 30.0f},   // mid vowel
    {1.0f, 25.0f, 30.0f},   // close front vowel
    {1.0f, 25.0f, 30.0f},   // open rounded vowel
    {1.0f, 25.0f, 30.0f},   // close rounded vowel
}};

// Beyond this a dominance is below kNegligible: alpha exp(-rate |tau|) with
// alpha at most 8 and rates of at least 15 per second is below 1e-6 past
// ln(8e6) / 15 = 1.06 s.
constexpr double kReachS = 1.1;
constexpr float kNegligible = 1e-6f;

}  // namespace

Dominance dominance_of(Viseme viseme) { return kDominance[static_cast<std::size_t>(viseme)]; }

float dominance_at(const VisemeSegment& segment, double t_s) {
  const Dominance d = dominance_of(segment.viseme);
  const double tau = t_s - segment.centre_s();
  const double rate = tau < 0 ? d.anticipation_per_s : d.carryover_per_s;
  return d.magnitude * static_cast<float>(std::exp(-rate * std::abs(tau)));
}

AuTargets coarticulate(std::span<const VisemeSegment> segments, double t_s) {
  AuTargets blended{};
  // The first segment that may still reach t_s: segments are in time order.
  auto it = std::lower_bound(segments.begin(), segments.end(), t_s - kReachS,
                             [](const VisemeSegment& s, double t) { return s.end_s < t; });
  double weight_sum = 0;
  std::array<double, codec::kAuChannelCount> sum{};
  for (; it != segments.end() && it->start_s <= t_s + kReachS; ++it) {
    const float weight = dominance_at(*it, t_s);
    if (weight < kNegligible) continue;
    const AuTargets& target = viseme_targets(it->viseme);
    for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += weight * target[c];
    weight_sum += weight;
  }
  if (weight_sum <= 0) return blended;
  for (std::size_t c = 0; c < sum.size(); ++c) blended[c] = static_cast<float>(sum[c] / weight_sum);
  return blended;
}

}  // namespace fw::speech
