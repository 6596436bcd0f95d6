#include "fw/script/diagnostic.hpp"

#include <gtest/gtest.h>

#include "fw/script/limits.hpp"

namespace fw::script {
namespace {

TEST(Diagnostic, FormatsAsFileLineColumn) {
  EXPECT_EQ(format_diagnostic("anger.fws", {Severity::error, {3, 7}, "expected 'end'"}), "anger.fws:3:7: expected 'end'");
  EXPECT_EQ(format_diagnostic("a.fws", {Severity::warning, {1, 1}, "AU 42"}), "a.fws:1:1: warning: AU 42");
}

TEST(Diagnostic, ListStopsAtTheErrorLimitWithOneLastWord) {
  DiagnosticList list;
  for (std::size_t i = 0; i < kMaxErrors + 50; ++i) {
    EXPECT_EQ(list.full(), i >= kMaxErrors);
    list.error({static_cast<int>(i) + 1, 1}, "error " + std::to_string(i));
  }
  EXPECT_EQ(list.error_count(), kMaxErrors + 50);
  ASSERT_EQ(list.items().size(), kMaxErrors);
  EXPECT_NE(list.items().back().message.find("too many errors"), std::string::npos);
}

TEST(Diagnostic, WarningsAreBoundedToo) {
  DiagnosticList list;
  for (std::size_t i = 0; i < kMaxWarnings * 2; ++i) list.warning({1, 1}, "w");
  EXPECT_EQ(list.items().size(), kMaxWarnings);
  EXPECT_EQ(list.error_count(), 0u);
  EXPECT_FALSE(list.full());
}

TEST(Diagnostic, PrintableEscapesAndCuts) {
  EXPECT_EQ(printable("abc"), "abc");
  EXPECT_EQ(printable(std::string("a\nb\xC3", 4)), "a\\x0Ab\\xC3");
  EXPECT_EQ(printable(std::string(100, 'x'), 5), "xxxxx...");
}

TEST(Diagnostic, NumbersReadBackTheSame) {
  EXPECT_EQ(number_text(2.5), "2.5");
  EXPECT_EQ(number_text(10), "10");
  EXPECT_EQ(number_text(0.3), "0.3");
}

}  // namespace
}  // namespace fw::script
