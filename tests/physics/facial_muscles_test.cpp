#include "fw/physics/facial_muscles.hpp"

#include <set>

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

TEST(FacialMuscles, AreFortyTwoWithUniqueNames) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < kMuscleCount; ++i) names.insert(muscle_name(i));
  EXPECT_EQ(names.size(), 42u);
  EXPECT_TRUE(names.contains("zygomatic_major_left"));
  EXPECT_TRUE(names.contains("orbicularis_oculi_orbital_right"));
}

TEST(FacialMuscles, IncludeThoseTheIssueNames) {
  for (const char* name : {"frontalis_inner", "corrugator", "zygomatic_major", "zygomatic_minor",
                           "levator_labii_superioris", "depressor_anguli_oris", "depressor_labii_inferioris",
                           "mentalis", "risorius", "buccinator", "procerus", "nasalis", "masseter",
                           "orbicularis_oris_peripheral", "orbicularis_oculi_orbital"})
    EXPECT_GE(muscle_index(name, true), 0) << name;
}

TEST(FacialMuscles, IndexAlternatesLeftAndRight) {
  const int left = muscle_index("risorius", true), right = muscle_index("risorius", false);
  EXPECT_EQ(left % 2, 0);
  EXPECT_EQ(right, left + 1);
  EXPECT_EQ(muscle_index("no_such_muscle", true), -1);
}

TEST(FacialMuscles, SphinctersAndLinearMusclesHaveSaneShapes) {
  for (const MuscleDefinition& m : facial_muscle_definitions()) {
    EXPECT_GE(m.strength, 0.0f) << m.name;
    if (m.kind == MuscleKind::sphincter) {
      EXPECT_GT(m.semi_axes.x, 0.0f) << m.name;
      EXPECT_GT(m.semi_axes.y, 0.0f) << m.name;
      EXPECT_GT(m.ring, 0.0f) << m.name;
    } else {
      EXPECT_GT(m.width, 0.0f) << m.name;
      EXPECT_GT(m.reach, 0.0f) << m.name;
    }
  }
}

}  // namespace
}  // namespace fw::physics
