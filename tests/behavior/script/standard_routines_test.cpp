#include "fw/script/standard_routines.hpp"

#include <gtest/gtest.h>

namespace fw::script {
namespace {

TEST(StandardRoutines, HoldsEveryLanguagesRoutinesOnce) {
  const RoutineLibrary library = standard_routines();
  for (const char* name :
       {"clear_all_frames", "keep_all_frames", "begin_keyframe", "au_intensity", "animate", "hold", "end_animation",
        "begin_au_definition", "control_point_displacement", "start_from_neutral", "start_from_current",
        "end_au_definition", "begin_emotion", "begin_stage", "stage_expression", "end_emotion",
        "begin_vascular_expression", "mpca_intensity", "end_vascular_expression"}) {
    const Routine* routine = library.find(name);
    ASSERT_NE(routine, nullptr) << name;
    EXPECT_NE(routine->run, nullptr) << name;
    EXPECT_FALSE(routine->summary.empty()) << name;
  }
  EXPECT_EQ(library.routines().size(), 19u) << "the README lists them all";
  EXPECT_EQ(library.finishes().size(), 1u);
}

}  // namespace
}  // namespace fw::script
