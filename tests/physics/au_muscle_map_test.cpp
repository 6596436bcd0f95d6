#include "fw/physics/au_muscle_map.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

TEST(AuMuscleMap, EveryCarriedActionUnitRecruitsAKnownMuscle) {
  for (int au : codec::kActionUnits) {
    ASSERT_FALSE(au_muscle_terms(au).empty()) << "AU " << au;
    for (const AuMuscleTerm& term : au_muscle_terms(au)) EXPECT_GE(muscle_index(term.muscle, true), 0) << term.muscle;
  }
  EXPECT_TRUE(au_muscle_terms(3).empty());
}

TEST(AuMuscleMap, APairedUnitDrivesItsOwnSide) {
  std::array<float, codec::kAuChannelCount> au{};
  au[static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left))] = 0.6f;
  const auto a = muscle_activations(au);
  EXPECT_FLOAT_EQ(a[static_cast<std::size_t>(muscle_index("zygomatic_major", true))], 0.6f);
  EXPECT_FLOAT_EQ(a[static_cast<std::size_t>(muscle_index("zygomatic_major", false))], 0.0f);
}

TEST(AuMuscleMap, AMidlineUnitDrivesBothSides) {
  std::array<float, codec::kAuChannelCount> au{};
  au[static_cast<std::size_t>(codec::au_channel(17, codec::AuSide::both))] = 1.0f;
  const auto a = muscle_activations(au);
  EXPECT_FLOAT_EQ(a[static_cast<std::size_t>(muscle_index("mentalis", true))], 1.0f);
  EXPECT_FLOAT_EQ(a[static_cast<std::size_t>(muscle_index("mentalis", false))], 1.0f);
}

TEST(AuMuscleMap, ClampsIntensitiesAndActivations) {
  std::array<float, codec::kAuChannelCount> au{};
  au.fill(7.0f);
  au[0] = std::nanf("");
  au[1] = -3.0f;
  for (float a : muscle_activations(au)) {
    EXPECT_GE(a, 0.0f);
    EXPECT_LE(a, 1.0f);
  }
}

}  // namespace
}  // namespace fw::physics
