#include "fw/render/frame_profile.hpp"

namespace fw::render {

namespace {

void add_to(std::map<std::string, double, std::less<>>& sums, std::string_view name, double seconds) {
  auto it = sums.find(name);
  if (it == sums.end()) it = sums.emplace(std::string(name), 0.0).first;
  it->second += seconds;
}

}  // namespace

void FrameProfile::add(std::string_view part, std::string_view variant, double seconds) {
  add_to(part_seconds, part, seconds);
  if (!variant.empty()) add_to(variant_seconds, variant, seconds);
}

std::map<std::string, double, std::less<>> FrameProfile::per_frame_ms(bool variants) const {
  std::map<std::string, double, std::less<>> out;
  if (frames <= 0) return out;
  for (const auto& [name, seconds] : variants ? variant_seconds : part_seconds) out[name] = 1000.0 * seconds / frames;
  return out;
}

}  // namespace fw::render
