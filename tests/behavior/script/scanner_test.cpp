#include "fw/script/scanner.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_reader.hpp"
#include "fw/script/limits.hpp"

namespace fw::script {
namespace {

struct Fixture {
  Grammar grammar;
  ScanTable table;
  explicit Fixture(const std::string& header_and_terminals) {
    std::vector<GrammarError> errors;
    EXPECT_TRUE(read_grammar({"t", header_and_terminals + "#Production\n<S> ::=\n#End\n"}, {}, grammar, errors));
    std::string error;
    EXPECT_TRUE(build_scan_table(grammar, table, error)) << error;
  }
  std::vector<Token> scan(std::string_view text) const {
    Scanner scanner(table, text);
    std::vector<Token> tokens;
    for (int guard = 0; guard < 1000; ++guard) {
      tokens.push_back(scanner.next());
      if (tokens.back().terminal == grammar.end_of_input()) break;
    }
    return tokens;
  }
};

const Fixture& expression_terminals() {
  static const Fixture f("#Scanner\ncomment #\n#Terminal\nend\nAnimate\nIntLit\nRealLit\nStringLit\nID\nOpen symbol [\n");
  return f;
}

TEST(Scanner, TokensValuesAndPositions) {
  const auto tokens = expression_terminals().scan("Animate 2 \"Smooth \\\"x\\\"\" # comment\n  -1.25 [Brow end");
  ASSERT_EQ(tokens.size(), 8u);
  EXPECT_EQ(tokens[0].terminal, 1);
  EXPECT_EQ(tokens[0].position, (SourcePosition{1, 1}));
  EXPECT_EQ(tokens[1].value.kind, ValueKind::integer);
  EXPECT_EQ(tokens[1].value.integer, 2);
  EXPECT_EQ(tokens[1].position, (SourcePosition{1, 9}));
  EXPECT_EQ(tokens[2].value.text, "Smooth \"x\"");
  EXPECT_EQ(tokens[3].value.kind, ValueKind::real);
  EXPECT_DOUBLE_EQ(tokens[3].value.real, -1.25);
  EXPECT_EQ(tokens[3].position, (SourcePosition{2, 3}));
  EXPECT_EQ(tokens[4].terminal, 6);
  EXPECT_EQ(tokens[5].value.text, "Brow");
  EXPECT_EQ(tokens[5].position, (SourcePosition{2, 10}));
  EXPECT_EQ(tokens[6].terminal, 0);
  EXPECT_EQ(tokens[7].terminal, expression_terminals().grammar.end_of_input());
  EXPECT_EQ(tokens[7].position, (SourcePosition{2, 18}));
}

TEST(Scanner, ByteOrderMarkAndCarriageReturnsAreInvisible) {
  const auto tokens = expression_terminals().scan("\xEF\xBB\xBF" "end\r\n+3\r\n");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].position, (SourcePosition{1, 1}));
  EXPECT_EQ(tokens[1].value.integer, 3);
  EXPECT_EQ(tokens[1].position, (SourcePosition{2, 1}));
}

TEST(Scanner, BadTextBecomesAnErrorTokenAndScanningGoesOn) {
  const auto tokens = expression_terminals().scan("@ end \"open\n\xC3\xA9 99999999999999999999 end");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[0].terminal, Token::kScanError);
  EXPECT_EQ(tokens[0].error, "unexpected character '@'");
  EXPECT_EQ(tokens[1].terminal, 0);
  EXPECT_EQ(tokens[2].terminal, Token::kScanError);
  EXPECT_NE(tokens[2].error.find("not closed"), std::string::npos);
  EXPECT_EQ(tokens[3].terminal, Token::kScanError);
  EXPECT_EQ(tokens[3].lexeme, "\xC3\xA9") << "a UTF-8 character is one error";
  EXPECT_EQ(tokens[3].position, (SourcePosition{2, 1}));
  EXPECT_EQ(tokens[4].terminal, Token::kScanError);
  EXPECT_NE(tokens[4].error.find("too large"), std::string::npos);
  EXPECT_EQ(tokens[5].terminal, 0);
}

TEST(Scanner, LongTokensAreCutButLongCommentsAreFine) {
  const std::string long_name(kMaxTokenBytes + 10, 'a');
  const auto tokens = expression_terminals().scan(long_name + " end # " + std::string(10000, 'c') + "\nend");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].terminal, Token::kScanError);
  EXPECT_NE(tokens[0].error.find("longer than"), std::string::npos);
  EXPECT_EQ(tokens[0].lexeme.size(), long_name.size()) << "the whole word is skipped";
  EXPECT_EQ(tokens[1].terminal, 0);
  EXPECT_EQ(tokens[2].terminal, 0);
  EXPECT_EQ(tokens[2].position, (SourcePosition{2, 1}));
}

TEST(Scanner, KeywordsMayIgnoreCaseAndUnknownWordsAreWhole) {
  const Fixture f("#Scanner\nkeywords case-insensitive\n#Terminal\nDone keyword done\nIntLit\n");
  const auto tokens = f.scan("DONE Done donee 5");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[0].terminal, 0);
  EXPECT_EQ(tokens[1].terminal, 0);
  EXPECT_EQ(tokens[2].terminal, Token::kScanError);
  EXPECT_EQ(tokens[2].error, "'donee' is not a word of this language");
  EXPECT_EQ(tokens[3].value.integer, 5);
}

TEST(Scanner, EndOfInputRepeats) {
  Scanner scanner(expression_terminals().table, "");
  EXPECT_EQ(scanner.next().terminal, expression_terminals().grammar.end_of_input());
  EXPECT_EQ(scanner.next().terminal, expression_terminals().grammar.end_of_input());
}

}  // namespace
}  // namespace fw::script
