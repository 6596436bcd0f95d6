// The committed golden files of the browser's ports still say what the C++
// computes now: a change of the C++ that is not written out (and so not
// followed by the browser's port, whose node tests read these files) fails
// here. Rewrite them with `cmake --build <build> --target web_golden`.
#include <ostream>

#include <gtest/gtest.h>

#include "golden_json.hpp"
#include "test_paths.hpp"

namespace fw::test::web_golden {

// Named in gtest's output rather than dumped as bytes (found by argument-
// dependent lookup, so beside GoldenSet's namespace, not in an anonymous one).
void PrintTo(const GoldenSet& set, std::ostream* out);
void PrintTo(const GoldenSet& set, std::ostream* out) { *out << set.name; }

namespace {

class CommittedGolden : public ::testing::TestWithParam<GoldenSet> {};

TEST_P(CommittedGolden, MatchesWhatTheCppComputesNow) {
  const GoldenSet& set = GetParam();
  const auto path = golden_path(std::filesystem::path(source_dir()) / "tests" / "vectors", set.name);
  const nlohmann::json committed = read_golden(path);
  ASSERT_FALSE(committed.is_discarded()) << "missing or broken " << path << ": build the web_golden target";
  const nlohmann::json now = set.make();
  EXPECT_EQ(first_difference(committed, now), "") << path << " is stale: build the web_golden target, then make "
                                                      "the browser's port follow (its node test reads the file)";
}

// The comparison itself can fail: one changed value is found and named.
TEST(FirstDifference, NamesTheFirstChangedValue) {
  const nlohmann::json a = {{"cases", {{{"step", "stop"}}, {{"step", "next_server"}}}}};
  nlohmann::json b = a;
  b["cases"][1]["step"] = "same_server";
  EXPECT_EQ(first_difference(a, a), "");
  const std::string d = first_difference(a, b);
  EXPECT_NE(d.find("/cases/1/step"), std::string::npos) << d;
  EXPECT_NE(d.find("next_server"), std::string::npos) << d;
}

INSTANTIATE_TEST_SUITE_P(Web, CommittedGolden, ::testing::ValuesIn(golden_sets()),
                         [](const ::testing::TestParamInfo<GoldenSet>& set) { return set.param.name; });

}  // namespace
}  // namespace fw::test::web_golden
