#include "fw/behavior/emotion_space.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fw/model/expressions.hpp"

namespace fw::behavior {

EmotionTemplate classify(const EmotionPoint& point) {
  std::size_t first = 0, second = 1;
  if (point[second] > point[first]) std::swap(first, second);
  for (std::size_t i = 2; i < kPrimaryCount; ++i) {
    if (point[i] > point[first]) {
      second = first;
      first = i;
    } else if (point[i] > point[second]) {
      second = i;
    }
  }
  EmotionTemplate t;
  t.intensity = point[first];
  if (point[first] < kNeutralRadius) return t;
  t.first = static_cast<Primary>(first);
  if (point[second] >= kNeutralRadius && point[second] >= kBlendRatio * point[first])
    t.second = static_cast<Primary>(second);
  return t;
}

std::string label(const EmotionTemplate& t) {
  if (!t.first) return "neutral";
  std::string s(kPrimaryNames[static_cast<std::size_t>(*t.first)]);
  if (t.second) {
    s += '+';
    s += kPrimaryNames[static_cast<std::size_t>(*t.second)];
  }
  return s;
}

std::optional<Primary> primary_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kPrimaryCount; ++i)
    if (kPrimaryNames[i] == name) return static_cast<Primary>(i);
  return std::nullopt;
}

EmotionPoint clamp_to_cube(EmotionPoint p) {
  for (float& v : p) v = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f);
  return p;
}

EmotionPoint decay_toward_neutral(const EmotionPoint& point, double dt_s, double half_life_s) {
  const float keep = static_cast<float>(std::exp2(-dt_s / half_life_s));
  EmotionPoint out = point;
  for (float& v : out) v *= keep;
  return out;
}

std::array<float, codec::kAuChannelCount> emotion_action_units(const EmotionPoint& point, float* lid_closure) {
  codec::FaceParams params;
  float lids = 0;
  for (std::size_t i = 0; i < kPrimaryCount; ++i) {
    if (point[i] <= 0) continue;
    // fw::model's table has the primaries first, in the same order.
    const auto e = static_cast<model::Expression>(i);
    model::apply_expression(e, point[i], params);
    lids = std::max(lids, model::expression_definition(e).lid_closure * point[i]);
  }
  if (lid_closure) *lid_closure = lids;
  return params.au;
}

}  // namespace fw::behavior
