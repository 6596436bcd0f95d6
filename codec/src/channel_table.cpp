#include "channel_table.hpp"

#include <numbers>

namespace fw::codec {
namespace {

constexpr float kAuStep = 1.0f / 256.0f;  // 0.2 mm on the vertex AU 27 moves most (50 mm), 0.04 mm for a brow
constexpr float kAngleStep = static_cast<float>(std::numbers::pi / 3600.0);  // 0.05 degree
constexpr float kTranslationStep = 0.125f;                                   // mm
constexpr float kLidStep = 1.0f / 128.0f;     // 0.08 mm of a 10 mm lid travel
constexpr float kColourStep = 1.0f / 64.0f;   // about 0.25 CIELAB units at full blush
// A corrective component at weight 1 moves the skin a few millimetres at
// most (the physics residual it stands for: 0.4 mm RMS, 3.4 mm at worst), so
// a step of 1/64 moves a vertex 0.05 mm at most (FORMAT.md, "Why these steps").
constexpr float kCorrectiveStep = 1.0f / 64.0f;

constexpr const char* kAuNames[kAuChannelCount] = {
    "au1_left",  "au1_right",  "au2_left",  "au2_right",  "au4_left",  "au4_right", "au5_left",  "au5_right",
    "au6_left",  "au6_right",  "au7_left",  "au7_right",  "au9",       "au10_left", "au10_right", "au12_left",
    "au12_right", "au14_left", "au14_right", "au15_left", "au15_right", "au17",     "au20_left", "au20_right",
    "au23",      "au24",       "au25",      "au26",       "au27"};

constexpr const char* kCorrectiveNames[kCorrectiveCount] = {"corrective0", "corrective1", "corrective2",
                                                            "corrective3", "corrective4", "corrective5"};

std::array<ChannelInfo, kChannelCount> make_table() {
  std::array<ChannelInfo, kChannelCount> t{};
  std::size_t c = 0;
  for (std::size_t i = 0; i < kAuChannelCount; ++i) {
    const bool right = kAuChannels[i].side == AuSide::right;
    t[c] = {kAuNames[i], ChannelGroup::action_units, kAuStep, 0, 256,
            static_cast<std::int8_t>(right ? static_cast<int>(c) - 1 : -1), -1};
    ++c;
  }
  t[c++] = {"head_yaw", ChannelGroup::head_rotation, kAngleStep, -1376, 1376, -1, -1};    // 1.2 rad
  t[c++] = {"head_pitch", ChannelGroup::head_rotation, kAngleStep, -917, 917, -1, -1};    // 0.8 rad
  t[c++] = {"head_roll", ChannelGroup::head_rotation, kAngleStep, -688, 688, -1, -1};     // 0.6 rad
  t[c++] = {"head_x", ChannelGroup::head_translation, kTranslationStep, -800, 800, -1, -1};
  t[c++] = {"head_y", ChannelGroup::head_translation, kTranslationStep, -800, 800, -1, -1};
  t[c++] = {"head_z", ChannelGroup::head_translation, kTranslationStep, -800, 800, -1, -1};
  t[c++] = {"eye_left_yaw", ChannelGroup::eyes, kAngleStep, -688, 688, -1, 29};      // 0.6 rad
  t[c++] = {"eye_left_pitch", ChannelGroup::eyes, kAngleStep, -573, 573, -1, 30};    // 0.5 rad
  t[c++] = {"eye_right_yaw", ChannelGroup::eyes, kAngleStep, -688, 688, 35, 29};
  t[c++] = {"eye_right_pitch", ChannelGroup::eyes, kAngleStep, -573, 573, 36, 30};
  t[c++] = {"lid_left", ChannelGroup::lids, kLidStep, 0, 128, -1, -1};
  t[c++] = {"lid_right", ChannelGroup::lids, kLidStep, 0, 128, 39, -1};
  t[c++] = {"blush_forehead", ChannelGroup::colour, kColourStep, 0, 64, -1, -1};
  t[c++] = {"blush_cheek_left", ChannelGroup::colour, kColourStep, 0, 64, -1, -1};
  t[c++] = {"blush_cheek_right", ChannelGroup::colour, kColourStep, 0, 64, 42, -1};
  t[c++] = {"blush_nose", ChannelGroup::colour, kColourStep, 0, 64, -1, -1};
  t[c++] = {"blush_sides", ChannelGroup::colour, kColourStep, 0, 64, -1, -1};
  t[c++] = {"pallor", ChannelGroup::colour, kColourStep, 0, 64, -1, -1};
  for (std::size_t k = 0; k < kCorrectiveCount; ++k)
    t[c++] = {kCorrectiveNames[k], ChannelGroup::correctives, kCorrectiveStep, -64, 64, -1, -1};  // [-1, 1]
  return t;
}

// [level][group]: action units, head rotation, head translation, eyes, lids,
// colour, correctives. The correctives coarsen a level ahead of the rest and
// end a level coarser (16 steps, 1/4 of a weight): they are the detail a
// viewer misses last, so a tight budget takes their bits first.
constexpr int kShift[kMaxQualityLevel + 1][kChannelGroupCount] = {
    {0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 1, 0, 0, 0}, {0, 0, 0, 1, 1, 0, 1}, {1, 1, 1, 2, 1, 1, 1},
    {1, 1, 1, 2, 2, 1, 2}, {2, 2, 2, 2, 2, 2, 2}, {2, 2, 2, 2, 3, 2, 3}, {3, 3, 3, 2, 3, 3, 4}};

}  // namespace

const std::array<ChannelInfo, kChannelCount>& channel_table() {
  static const std::array<ChannelInfo, kChannelCount> table = make_table();
  return table;
}

const std::array<GroupSpan, kChannelGroupCount>& group_spans() {
  static const std::array<GroupSpan, kChannelGroupCount> spans = {
      GroupSpan{0, kAuChannelCount}, GroupSpan{kAuChannelCount, 3}, GroupSpan{kAuChannelCount + 3, 3},
      GroupSpan{kAuChannelCount + 6, 4}, GroupSpan{kAuChannelCount + 10, 2},
      GroupSpan{kAuChannelCount + 12, kColourRegionCount + 1},
      GroupSpan{kAuChannelCount + 12 + kColourRegionCount + 1, kCorrectiveCount}};
  return spans;
}

int group_shift(int level, std::size_t group) {
  return kShift[static_cast<std::size_t>(level)][group];
}

CodedRange coded_range(std::size_t channel) { return coded_ranges()[channel]; }

const std::array<CodedRange, kChannelCount>& coded_ranges() {
  // Worked out once: the reconstruction asks for every channel every tick.
  static const std::array<CodedRange, kChannelCount> ranges = [] {
    std::array<CodedRange, kChannelCount> r{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const ChannelInfo& info = channel_table()[c];
      r[c] = {info.min_q, info.max_q};
      if (info.base >= 0) {
        const ChannelInfo& base = channel_table()[static_cast<std::size_t>(info.base)];
        r[c] = {info.min_q + base.min_q, info.max_q + base.max_q};
      }
    }
    return r;
  }();
  return ranges;
}

std::int32_t max_velocity(std::size_t channel) {
  const CodedRange range = coded_range(channel);
  return (range.max - range.min) * kSubSteps;
}

QuantisedParams fields_from_coded(const ChannelValues& coded) {
  QuantisedParams fields = coded;
  const auto& table = channel_table();
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    if (table[c].base < 0) continue;
    const std::int32_t v = coded[c] - coded[static_cast<std::size_t>(table[c].base)];
    fields[c] = v < table[c].min_q ? table[c].min_q : (v > table[c].max_q ? table[c].max_q : v);
  }
  return fields;
}

}  // namespace fw::codec
