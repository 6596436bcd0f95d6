#include "fw/codec/face_params.hpp"

#include <set>
#include <type_traits>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(FaceParams, CarriesTheActionUnitsTheFaceNeeds) {
  for (int au : {1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 24, 25, 26, 27})
    EXPECT_GE(action_unit_index(au), 0) << "AU " << au;
  EXPECT_EQ(action_unit_index(3), -1);
  EXPECT_EQ(std::set<int>(kActionUnits.begin(), kActionUnits.end()).size(), kActionUnitCount) << "no duplicates";
}

TEST(FaceParams, IsPlainDataAtRestByDefault) {
  static_assert(std::is_trivially_copyable_v<FaceParams>);
  const FaceParams rest;
  for (float v : rest.au) EXPECT_EQ(v, 0.0f);
  EXPECT_EQ(rest.lid_left, 0.0f);
  EXPECT_EQ(rest.pallor, 0.0f);
}

}  // namespace
}  // namespace fw::codec
