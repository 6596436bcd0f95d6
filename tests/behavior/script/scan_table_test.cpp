#include "fw/script/scan_table.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_reader.hpp"
#include "fw/script/limits.hpp"

namespace fw::script {
namespace {

Grammar grammar_of(const std::string& terminals) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_TRUE(read_grammar({"t", "#Terminal\n" + terminals + "#Production\n<S> ::=\n#End\n"}, {}, g, errors));
  return g;
}

// Runs the table from the start over `text` and returns what the longest
// accepted prefix is, and how long.
std::pair<int, std::size_t> longest(const ScanTable& t, std::string_view text) {
  int state = 0, accept = ScanTable::kAcceptNothing;
  std::size_t length = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    state = t.step(state, static_cast<unsigned char>(text[i]));
    if (state == ScanTable::kNoState) break;
    if (t.accept[static_cast<std::size_t>(state)] != ScanTable::kAcceptNothing) {
      accept = t.accept[static_cast<std::size_t>(state)];
      length = i + 1;
    }
  }
  return {accept, length};
}

TEST(ScanTable, KeywordsBeatNamesOfTheSameLengthAndLongerNamesBeatKeywords) {
  const Grammar g = grammar_of("Animate\nID\n");
  ScanTable t;
  std::string error;
  ASSERT_TRUE(build_scan_table(g, t, error)) << error;
  EXPECT_EQ(longest(t, "Animate 2"), (std::pair<int, std::size_t>{0, 7}));
  EXPECT_EQ(longest(t, "Animated"), (std::pair<int, std::size_t>{1, 8}));
  EXPECT_EQ(longest(t, "Anim"), (std::pair<int, std::size_t>{1, 4}));
}

TEST(ScanTable, NumbersSymbolsAndStrings) {
  const Grammar g = grammar_of("IntLit\nRealLit\nStringLit\nMinus symbol -\nArrow symbol ->\n");
  ScanTable t;
  std::string error;
  ASSERT_TRUE(build_scan_table(g, t, error)) << error;
  EXPECT_EQ(longest(t, "-12 "), (std::pair<int, std::size_t>{0, 3}));
  EXPECT_EQ(longest(t, "-1.50e3x"), (std::pair<int, std::size_t>{1, 7}));
  EXPECT_EQ(longest(t, "12."), (std::pair<int, std::size_t>{0, 2})) << "a dot needs digits after it";
  EXPECT_EQ(longest(t, "- 1"), (std::pair<int, std::size_t>{3, 1}));
  EXPECT_EQ(longest(t, "->"), (std::pair<int, std::size_t>{4, 2}));
  EXPECT_EQ(longest(t, R"("a \"b\" c" rest)"), (std::pair<int, std::size_t>{2, 11}));
  EXPECT_EQ(longest(t, "\"open\nx\"").first, ScanTable::kAcceptNothing) << "strings end on their line";
  EXPECT_EQ(longest(t, "  \n\t x").first, ScanTable::kAcceptSkip);
}

TEST(ScanTable, WithoutIntegersARealMayBeWholeAndWithoutNamesAWordIsUnknown) {
  const Grammar g = grammar_of("Go\nRealLit\n");
  ScanTable t;
  std::string error;
  ASSERT_TRUE(build_scan_table(g, t, error)) << error;
  EXPECT_EQ(longest(t, "12 "), (std::pair<int, std::size_t>{1, 2}));
  EXPECT_EQ(longest(t, "Go "), (std::pair<int, std::size_t>{0, 2}));
  EXPECT_EQ(longest(t, "Gone").first, ScanTable::kAcceptUnknownWord);
}

TEST(ScanTable, BytesTheAutomatonTreatsAlikeShareAClass) {
  const Grammar g = grammar_of("Go\nIntLit\n");
  ScanTable t;
  std::string error;
  ASSERT_TRUE(build_scan_table(g, t, error)) << error;
  EXPECT_LT(t.class_count, 16);
  EXPECT_EQ(t.byte_class['3'], t.byte_class['7']);
  EXPECT_NE(t.byte_class['G'], t.byte_class['H']);
  EXPECT_EQ(t.next.size(), static_cast<std::size_t>(t.state_count() * t.class_count));
  EXPECT_EQ(t.end_of_input, 2);
}

// The grammar limits keep the automaton near kMaxScanStates at most; the
// largest keywords and comment introducers the limits allow go just past it,
// and that is an error, not a table of unbounded size.
TEST(ScanTable, TooManyStatesIsAnErrorNotAnExplosion) {
  std::string header = "#Scanner\n";
  for (char c : std::string("$%&*")) header += "comment " + std::string(kMaxSpellingBytes, c) + "\n";
  std::string terminals;
  for (std::size_t i = 0; i < kMaxTerminals; ++i) {
    std::string word(kMaxSpellingBytes, 'z');
    word[0] = static_cast<char>('a' + i % 26);
    word[1] = static_cast<char>('a' + i / 26);
    terminals += word + "\n";
  }
  Grammar g;
  std::vector<GrammarError> errors;
  ASSERT_TRUE(read_grammar({"t", header + "#Terminal\n" + terminals + "#Production\n<S> ::=\n#End\n"}, {}, g, errors));
  ASSERT_EQ(g.terminals.size(), kMaxTerminals);
  ScanTable t;
  std::string error;
  EXPECT_FALSE(build_scan_table(g, t, error));
  EXPECT_NE(error.find("scanner states"), std::string::npos) << error;

  // Without the comment introducers it fits.
  g.scanner.comment_introducers.clear();
  EXPECT_TRUE(build_scan_table(g, t, error)) << error;
  EXPECT_LE(static_cast<std::size_t>(t.state_count()), kMaxScanStates);
}

}  // namespace
}  // namespace fw::script
