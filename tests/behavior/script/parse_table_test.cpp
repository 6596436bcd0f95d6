#include "fw/script/parse_table.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_reader.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::joined;

Grammar grammar_from(const std::string& text, const std::string& name = "t.grammar") {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_TRUE(read_grammar({name, text}, {}, g, errors)) << joined(errors);
  return g;
}

TerminalSet terminals(const Grammar& g, std::initializer_list<const char*> names) {
  TerminalSet set;
  for (const char* name : names) {
    const int t = std::string(name) == "$" ? g.end_of_input() : g.terminal_index(name);
    EXPECT_GE(t, 0) << name;
    set.set(static_cast<std::size_t>(t));
  }
  return set;
}

TEST(ParseTable, FirstFollowAndTableOfThePapersGrammar) {
  const Grammar g = grammar_from(test::read_source("tests/behavior/script/data/paper_expression.grammar"));
  ParseTable t;
  std::vector<GrammarError> errors;
  ASSERT_TRUE(build_parse_table(g, t, errors)) << joined(errors);
  const auto nt = [&](const char* name) { return static_cast<std::size_t>(g.nonterminal_index(name)); };
  EXPECT_EQ(t.first[nt("START")], terminals(g, {"ClearAllFrame", "KeepAllFrame"}));
  EXPECT_EQ(t.first[nt("ACTIONS")], terminals(g, {"BeginKeyFrame", "Animate"}));
  EXPECT_TRUE(t.nullable[nt("ACTIONS")]);
  EXPECT_TRUE(t.nullable[nt("AULIST")]);
  EXPECT_FALSE(t.nullable[nt("ACTION")]);
  // A sentence may be followed by the next sentence or the end.
  EXPECT_EQ(t.follow[nt("START")], terminals(g, {"ClearAllFrame", "KeepAllFrame", "$"}));
  EXPECT_EQ(t.follow[nt("AULIST")], terminals(g, {"BeginKeyFrame", "Animate", "end"}));
  EXPECT_EQ(t.follow[nt("AUID")], terminals(g, {"Reallit"}));
  // <AULIST> ::= (nothing) is production 6, chosen on what follows a list.
  EXPECT_EQ(t.production_for(g.nonterminal_index("AULIST"), g.terminal_index("end")), 6);
  EXPECT_EQ(t.production_for(g.nonterminal_index("AULIST"), g.terminal_index("IntLit")), 5);
  EXPECT_EQ(t.production_for(g.nonterminal_index("AULIST"), g.terminal_index("StringLit")), ParseTable::kNoProduction);
  EXPECT_EQ(t.expected(g.nonterminal_index("AULIST")), terminals(g, {"IntLit", "BeginKeyFrame", "Animate", "end"}));
}

TEST(ParseTable, ANonLl1GrammarIsRejectedNamingTheConflict) {
  const Grammar g = grammar_from(test::read_source("tests/behavior/script/data/not_ll1.grammar"), "not_ll1.grammar");
  ParseTable t;
  std::vector<GrammarError> errors;
  ASSERT_FALSE(build_parse_table(g, t, errors));
  ASSERT_EQ(errors.size(), 1u) << joined(errors);
  const std::string& message = errors[0].message;
  EXPECT_NE(message.find("not LL(1)"), std::string::npos) << message;
  EXPECT_NE(message.find("<ACTION>"), std::string::npos) << message;
  EXPECT_NE(message.find("'BeginKeyFrame'"), std::string::npos) << message;
  EXPECT_NE(message.find("<ACTION> ::= BeginKeyFrame <AUS> (not_ll1.grammar:10)"), std::string::npos) << message;
  EXPECT_NE(message.find("<ACTION> ::= BeginKeyFrame IntLit (not_ll1.grammar:11)"), std::string::npos) << message;
  EXPECT_EQ(errors[0].where.line, 11);
}

TEST(ParseTable, AnEmptyAlternativeThatCollidesWithWhatFollowsIsAConflict) {
  // <OPT> may be empty and is followed by x, which it can also start with.
  const Grammar g = grammar_from("#Terminal\nx\ny\n#Production\n<S> ::= y <OPT> x\n<OPT> ::= x\n<OPT> ::=\n#End\n");
  ParseTable t;
  std::vector<GrammarError> errors;
  ASSERT_FALSE(build_parse_table(g, t, errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("can derive nothing and it can follow <OPT>"), std::string::npos) << errors[0].message;
  EXPECT_NE(errors[0].message.find("'x'"), std::string::npos) << errors[0].message;
}

TEST(ParseTable, LeftRecursionIsAConflict) {
  const Grammar g = grammar_from("#Terminal\nx\n#Production\n<S> ::= <L>\n<L> ::= <L> x\n<L> ::= x\n#End\n");
  ParseTable t;
  std::vector<GrammarError> errors;
  ASSERT_FALSE(build_parse_table(g, t, errors));
  EXPECT_NE(joined(errors).find("remove left recursion"), std::string::npos) << joined(errors);
}

TEST(ParseTable, EveryNonterminalMustFinishAndSentencesCannotBeEmpty) {
  ParseTable t;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(build_parse_table(grammar_from("#Terminal\nx\n#Production\n<S> ::= x <R>\n<R> ::= x <R>\n#End\n"), t, errors));
  EXPECT_NE(joined(errors).find("<R> never derives a finished sentence"), std::string::npos) << joined(errors);
  EXPECT_FALSE(build_parse_table(grammar_from("#Terminal\nx\n#Production\n<S> ::= x\n<S> ::=\n#End\n"), t, errors));
  EXPECT_NE(joined(errors).find("can derive an empty sentence"), std::string::npos) << joined(errors);
}

}  // namespace
}  // namespace fw::script
