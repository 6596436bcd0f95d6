#include "channel_table.hpp"

#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(ChannelTable, HasOneChannelPerFaceParamsFieldInFieldOrder) {
  const auto& t = channel_table();
  static_assert(kChannelCount == 53);
  EXPECT_EQ(t[0].name, "au1_left");
  EXPECT_EQ(t[kAuChannelCount - 1].name, "au27");
  EXPECT_EQ(t[29].name, "head_yaw");
  EXPECT_EQ(t[35].name, "eye_left_yaw");
  EXPECT_EQ(t[46].name, "pallor");
  EXPECT_EQ(t[47].name, "corrective0");
  EXPECT_EQ(t[52].name, "corrective5");
  std::set<std::string_view> names;
  for (const ChannelInfo& c : t) names.insert(c.name);
  EXPECT_EQ(names.size(), kChannelCount);
  for (std::size_t i = 0; i < kAuChannelCount; ++i) {
    const std::string expected = "au" + std::to_string(kAuChannels[i].au);
    EXPECT_EQ(std::string(t[i].name).rfind(expected, 0), 0u) << t[i].name;
  }
}

TEST(ChannelTable, RangesCoverTheFaceParamsRanges) {
  // FaceParams documents these ranges (face_params.hpp).
  const std::pair<std::size_t, double> limits[] = {{29, 1.2}, {30, 0.8}, {31, 0.6}, {32, 100}, {35, 0.6}, {36, 0.5}};
  for (const auto& [c, limit] : limits) {
    const ChannelInfo& info = channel_table()[c];
    EXPECT_GE(info.max_q * static_cast<double>(info.step), limit) << info.name;
    EXPECT_LE(info.min_q * static_cast<double>(info.step), -limit) << info.name;
    EXPECT_LT((info.max_q - 1) * static_cast<double>(info.step), limit) << info.name << ": no wasted range";
  }
  for (std::size_t c = 0; c < kAuChannelCount; ++c) EXPECT_EQ(channel_table()[c].max_q * channel_table()[c].step, 1.0f);
  EXPECT_EQ(channel_table()[39].max_q * channel_table()[39].step, 1.0f);
  EXPECT_EQ(channel_table()[46].max_q * channel_table()[46].step, 1.0f);
}

TEST(ChannelTable, CorrectivesCoverMinusOneToOneAndComeLast) {
  // FaceParams::corrective: six weights in [-1, 1], after everything schema 1 carried.
  for (std::size_t k = 0; k < kCorrectiveCount; ++k) {
    const ChannelInfo& info = channel_table()[kChannelCount - kCorrectiveCount + k];
    EXPECT_EQ(info.group, ChannelGroup::correctives) << info.name;
    EXPECT_EQ(info.max_q * info.step, 1.0f) << info.name;
    EXPECT_EQ(info.min_q * info.step, -1.0f) << info.name;
    EXPECT_EQ(info.partner, -1);
    EXPECT_EQ(info.base, -1);
  }
  FaceParams p;
  p.corrective = {0.5f, -0.25f, 1.0f, -1.0f, 1.0f / 64, 0.0f};
  for (std::size_t k = 0; k < kCorrectiveCount; ++k)
    EXPECT_EQ(channel_value(p, kChannelCount - kCorrectiveCount + k), p.corrective[k]) << "field order";
}

TEST(ChannelTable, CorrectivesCoarsenNoLaterThanAnyOtherGroup) {
  // A tight budget takes the correctives' precision first (FORMAT.md, "Quality levels").
  const auto correctives = group_index(ChannelGroup::correctives);
  for (int level = 0; level <= kMaxQualityLevel; ++level)
    for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
      if (g != group_index(ChannelGroup::eyes)) {
        EXPECT_GE(group_shift(level, correctives), group_shift(level, g)) << "level " << level << " group " << g;
      }
    }
}

TEST(ChannelTable, PartnersAreLeftSidesOfTheSameKindAndComeFirst) {
  const auto& t = channel_table();
  int partnered = 0;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    if (t[c].partner < 0) continue;
    ++partnered;
    const ChannelInfo& p = t[static_cast<std::size_t>(t[c].partner)];
    EXPECT_LT(static_cast<std::size_t>(t[c].partner), c);
    EXPECT_EQ(p.group, t[c].group);
    EXPECT_EQ(p.min_q, t[c].min_q);
    EXPECT_EQ(p.max_q, t[c].max_q);
    EXPECT_LT(p.partner, 0) << "no chains";
    EXPECT_NE(std::string(t[c].name).find("right"), std::string::npos) << t[c].name;
  }
  EXPECT_EQ(partnered, 11 + 2 + 1 + 1) << "11 paired AUs, two eye angles, a lid, a cheek";
}

TEST(ChannelTable, EyesAreCodedAsGazeInTheWorld) {
  for (std::size_t c = 35; c < 39; ++c) {
    const int base = channel_table()[c].base;
    ASSERT_GE(base, 0);
    EXPECT_EQ(channel_table()[static_cast<std::size_t>(base)].group, ChannelGroup::head_rotation);
    EXPECT_EQ(channel_table()[static_cast<std::size_t>(base)].step, channel_table()[c].step) << "same unit";
    EXPECT_LT(static_cast<std::size_t>(base), c);
  }
  EXPECT_EQ(coded_range(35).max, 688 + 1376);
  EXPECT_EQ(coded_range(36).min, -573 - 917);
  QuantisedParams coded{};
  coded[29] = 100;
  coded[35] = 150;
  coded[37] = 100 + 5000;  // beyond the eye's range: clamped
  const QuantisedParams fields = fields_from_coded(coded);
  EXPECT_EQ(fields[35], 50);
  EXPECT_EQ(fields[37], 688);
  EXPECT_EQ(fields[29], 100);
}

TEST(ChannelTable, GroupsAreContiguousAndCoverEveryChannel) {
  std::size_t next = 0;
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    EXPECT_EQ(group_spans()[g].first, next);
    for (std::size_t c = next; c < next + group_spans()[g].count; ++c)
      EXPECT_EQ(group_index(channel_table()[c].group), g) << channel_table()[c].name;
    next += group_spans()[g].count;
  }
  EXPECT_EQ(next, kChannelCount);
}

TEST(ChannelTable, ShiftsGrowWithTheLevelAndKeepGazeFine) {
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    EXPECT_EQ(group_shift(0, g), 0);
    for (int level = 1; level <= kMaxQualityLevel; ++level) EXPECT_GE(group_shift(level, g), group_shift(level - 1, g));
  }
  // An eye's quantisation error stays at or under 0.1 degree at every level.
  for (int level = 0; level <= kMaxQualityLevel; ++level)
    EXPECT_LE(std::ldexp(channel_table()[35].step, group_shift(level, 3)) / 2 * 180 / 3.14159265, 0.1001);
}

TEST(ChannelTable, DampingIsTheDocumentedRecurrence) {
  EXPECT_EQ(damp(1000, 0), 1000);
  EXPECT_EQ(damp(1000, 7), 750);
  EXPECT_EQ(damp(-1000, 7), -750) << "symmetric: truncates toward zero";
  EXPECT_EQ(damp(1000, 1), 1000 - (3000 >> 6));
  EXPECT_EQ(damp(3, 1), 2) << "at least one sub-step a tick: the glide ends";
  EXPECT_EQ(damp(-1, 5), 0);
}

}  // namespace
}  // namespace fw::codec
