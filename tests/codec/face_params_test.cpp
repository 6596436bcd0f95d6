#include "fw/codec/face_params.hpp"

#include <set>
#include <type_traits>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(FaceParams, CarriesTheActionUnitsTheFaceNeeds) {
  for (int au : {1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 24, 25, 26, 27}) {
    if (is_bilateral(au)) {
      EXPECT_GE(au_channel(au, AuSide::left), 0) << "AU " << au;
      EXPECT_GE(au_channel(au, AuSide::right), 0) << "AU " << au;
    } else {
      EXPECT_GE(au_channel(au, AuSide::both), 0) << "AU " << au;
    }
  }
  EXPECT_EQ(au_channel(3, AuSide::both), -1);
  std::set<std::pair<int, int>> unique;
  for (const AuChannel& c : kAuChannels) unique.insert({c.au, static_cast<int>(c.side)});
  EXPECT_EQ(unique.size(), kAuChannelCount) << "no channel twice";
}

TEST(FaceParams, IsPlainDataAtRestByDefault) {
  static_assert(std::is_trivially_copyable_v<FaceParams>);
  const FaceParams rest;
  for (float v : rest.au) EXPECT_EQ(v, 0.0f);
  EXPECT_EQ(rest.lid_left, 0.0f);
  EXPECT_EQ(rest.pallor, 0.0f);
}

TEST(FaceParams, SetAuReachesBothSidesOfPairedMuscles) {
  FaceParams p;
  p.set_au(12, 0.7f);
  EXPECT_FLOAT_EQ(p.au_intensity(12, AuSide::left), 0.7f);
  EXPECT_FLOAT_EQ(p.au_intensity(12, AuSide::right), 0.7f);
  p.au[static_cast<std::size_t>(au_channel(12, AuSide::right))] = 0.1f;  // a smirk
  EXPECT_FLOAT_EQ(p.au_intensity(12), 0.4f);
  p.set_au(26, 0.5f);
  EXPECT_FLOAT_EQ(p.au_intensity(26), 0.5f);
  EXPECT_FLOAT_EQ(p.au_intensity(26, AuSide::left), 0.5f) << "midline AUs read the same from any side";
  p.set_au(3, 1.0f);  // not carried: ignored
  EXPECT_FLOAT_EQ(p.au_intensity(3), 0.0f);
}

}  // namespace
}  // namespace fw::codec
