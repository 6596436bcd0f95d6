#include "fw/script/routine_library.hpp"

#include <gtest/gtest.h>

namespace fw::script {
namespace {

SemanticValue nothing(RoutineCall&) { return {}; }
void finish_nothing(ScriptBuilder&, DiagnosticList&) {}

TEST(RoutineLibrary, FindsRoutinesByNameAndRefusesTwins) {
  RoutineLibrary library;
  EXPECT_TRUE(library.add({"begin_keyframe", {}, ValueKind::none, nothing, "starts a keyframe"}));
  EXPECT_TRUE(library.add({"au_intensity", {{kIntegerParameter, "the AU"}, {kNumberParameter, "its intensity"}},
                           ValueKind::none, nothing, "sets an AU"}));
  EXPECT_FALSE(library.add({"begin_keyframe", {}, ValueKind::none, nothing, "again"}));
  ASSERT_NE(library.find("au_intensity"), nullptr);
  EXPECT_EQ(library.find("au_intensity")->parameters.size(), 2u);
  EXPECT_EQ(library.find("no_such_routine"), nullptr);
  EXPECT_EQ(library.routines().size(), 2u);
  library.add_finish(finish_nothing);
  EXPECT_EQ(library.finishes().size(), 1u);
}

TEST(RoutineLibrary, DescribesValueKindsForMessages) {
  EXPECT_EQ(describe_kinds(kNumberParameter), "a number");
  EXPECT_EQ(describe_kinds(kIntegerParameter), "an integer");
  EXPECT_EQ(describe_kinds(kinds_of(ValueKind::real)), "a real number");
  EXPECT_EQ(describe_kinds(kTextParameter | kOptional), "a text or nothing");
  EXPECT_EQ(describe_kinds(kinds_of(ValueKind::none)), "nothing");
}

}  // namespace
}  // namespace fw::script
