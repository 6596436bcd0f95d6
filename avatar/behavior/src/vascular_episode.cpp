#include "fw/behavior/vascular_episode.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <utility>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"

namespace fw::behavior {
namespace {

// Blushing as in the paper's Figure 4 (blush1 as printed, blush2 and blush3
// spreading from the cheeks as "blushing commonly starts at the cheeks"), and
// pallor: the whole face drains quickly and recovers slowly.
constexpr std::string_view kScript = R"([emotion blushing
  [stage1 duration 10 [expression blush1 intensity 0.9]]
  [stage2 duration 10 [expression blush2 intensity 0.8]]
  [stage3 duration 60 [expression blush3 intensity 0.6]]
  [stage4 duration 20]]
[expression blush1 [mpca forehead intensity 0.4] [mpca cheeks intensity 0.6] [mpca ears intensity 0.3]]
[expression blush2 [mpca forehead intensity 0.5] [mpca cheeks intensity 0.8] [mpca ears intensity 0.5] [mpca nose intensity 0.3]]
[expression blush3 [mpca head intensity 0.3] [mpca cheeks intensity 0.7]]
[emotion pallor
  [stage1 duration 15 [expression pale intensity 1.0]]
  [stage2 duration 45 [expression pale intensity 0.8]]
  [stage3 duration 40]]
[expression pale [mpca pallor intensity 0.7] [mpca cheeks intensity 0.0]]
)";

const std::map<std::string, script::VascularEmotion, std::less<>>& builtins() {
  static const auto emotions = [] {
    std::map<std::string, script::VascularEmotion, std::less<>> m;
    const script::ScriptResult result = script::parse_script(script::default_language(), kScript);
    assert(result.ok());
    for (const script::VascularEmotion& e : result.meaning.emotions) m[e.name] = e;
    return m;
  }();
  return emotions;
}

}  // namespace

std::string_view builtin_vascular_script() { return kScript; }

const script::VascularEmotion& builtin_vascular_emotion(std::string_view name) {
  const auto it = builtins().find(name);
  assert(it != builtins().end() && it->second.colours_resolved);
  return it->second;
}

script::ColourChannels episode_colour(const script::VascularEmotion& emotion, double t_s, double span_s, float gain) {
  script::ColourChannels out{};
  if (t_s < 0 || t_s >= span_s || span_s <= 0 || emotion.colour_keys.empty()) return out;
  const double percent = 100.0 * t_s / span_s;
  const auto& keys = emotion.colour_keys;
  std::size_t i = 1;
  while (i < keys.size() && keys[i].at_percent < percent) ++i;
  if (i >= keys.size()) return out;
  const script::ColourKey& a = keys[i - 1];
  const script::ColourKey& b = keys[i];
  const double span = std::max(1e-9, b.at_percent - a.at_percent);
  double s = std::clamp((percent - a.at_percent) / span, 0.0, 1.0);
  s = s * s * (3 - 2 * s);  // blood flow eases in and out of each stage
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = gain * (a.channels[c] + (b.channels[c] - a.channels[c]) * s);
  return out;
}

float VascularState::audience_gain(int attending) {
  const int n = std::clamp(attending, 0, 4);
  return n == 0 ? 0.45f : 0.45f + 0.55f * static_cast<float>(n) / 4.0f;
}

double VascularState::blush_span_s(int attending) { return 14.0 + 4.0 * std::clamp(attending, 0, 4); }

void VascularState::start(const script::VascularEmotion& emotion, double span_s, float gain) {
  std::erase_if(episodes_, [&](const Episode& e) { return e.emotion.name == emotion.name; });
  episodes_.push_back({emotion, span_s, gain, 0});
}

bool VascularState::blushing() const {
  return std::any_of(episodes_.begin(), episodes_.end(), [](const Episode& e) { return e.emotion.name == "blushing"; });
}

void VascularState::embarrass() { embarrassed_ = true; }

std::optional<std::string> VascularState::step(double dt_s, int attending, int others, float fear, float surprise) {
  for (Episode& e : episodes_) e.t_s += dt_s;
  std::erase_if(episodes_, [](const Episode& e) { return e.t_s >= e.span_s; });
  since_pallor_s_ += dt_s;
  since_blush_s_ += dt_s;
  const bool spotlit = attending >= kSpotlightFaces && 2 * attending >= others;
  spotlight_s_ = spotlit ? spotlight_s_ + dt_s : 0;

  for (Episode& e : episodes_) {
    // A growing audience deepens a blush already under way.
    if (e.emotion.name == "blushing") e.gain = std::max(e.gain, audience_gain(attending));
  }
  const bool embarrassed = std::exchange(embarrassed_, false);
  if (!blushing() && since_blush_s_ >= kBlushRefractoryS && (embarrassed || spotlight_s_ >= kSpotlightS)) {
    start(builtin_vascular_emotion("blushing"), blush_span_s(attending), audience_gain(attending));
    since_blush_s_ = 0;
    spotlight_s_ = 0;
    return std::string("blush start (") + (embarrassed ? "embarrassed, " : "centre of attention, ") +
           std::to_string(attending) + " attending)";
  }
  if ((fear >= kPallorFear || surprise >= kShockSurprise) && since_pallor_s_ >= kPallorRefractoryS) {
    start(builtin_vascular_emotion("pallor"), 8.0, std::max(fear, surprise));
    since_pallor_s_ = 0;
    return std::string("pallor start");
  }
  return std::nullopt;
}

void VascularState::write(codec::FaceParams& params) const {
  script::ColourChannels sum{};
  for (const Episode& e : episodes_) {
    const script::ColourChannels c = episode_colour(e.emotion, e.t_s, e.span_s, e.gain);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = std::max(sum[i], c[i]);
  }
  for (std::size_t r = 0; r < codec::kColourRegionCount; ++r) params.blush[r] = static_cast<float>(std::clamp(sum[r], 0.0, 1.0));
  params.pallor = static_cast<float>(std::clamp(sum[script::kPallorChannel], 0.0, 1.0));
}

}  // namespace fw::behavior
