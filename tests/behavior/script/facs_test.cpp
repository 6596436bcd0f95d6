#include "fw/script/facs.hpp"

#include <gtest/gtest.h>

#include "fw/codec/face_params.hpp"

namespace fw::script {
namespace {

TEST(Facs, KnowsTheFacsCodes) {
  for (int au : {1, 2, 4, 9, 27, 39, 41, 42, 46, 51, 58, 61, 66}) EXPECT_TRUE(is_facs_action_unit(au)) << au;
  for (long long au : {-1LL, 0LL, 3LL, 40LL, 47LL, 50LL, 59LL, 60LL, 67LL, 100LL, 1LL << 40})
    EXPECT_FALSE(is_facs_action_unit(au)) << au;
  EXPECT_EQ(facs_action_unit_name(1), "inner brow raiser");
  EXPECT_EQ(facs_action_unit_name(42), "slit");
  EXPECT_EQ(facs_action_unit_name(3), "");
  EXPECT_EQ(facs_ranges_text(), "1-2, 4-39, 41-46, 51-58 and 61-66");
}

TEST(Facs, FacesCarryExactlyTheCodecsActionUnits) {
  for (auto au : codec::kActionUnits) {
    EXPECT_TRUE(is_facs_action_unit(au)) << int(au);
    EXPECT_TRUE(is_carried_by_faces(au)) << int(au);
  }
  EXPECT_FALSE(is_carried_by_faces(42));
  EXPECT_FALSE(is_carried_by_faces(11));
  EXPECT_EQ(carried_action_units_text(), "1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 24, 25, 26, 27");
}

}  // namespace
}  // namespace fw::script
