#include "fw/script/grammar.hpp"

#include <gtest/gtest.h>

namespace fw::script {
namespace {

Grammar small_grammar() {
  Grammar g;
  g.name = "g.grammar";
  g.terminals = {{"Animate", TerminalKind::keyword, "Animate", {}},
                 {"Open", TerminalKind::symbol, "[", {}},
                 {"IntLit", TerminalKind::integer, "", {}},
                 {"RealLit", TerminalKind::real, "", {}},
                 {"StringLit", TerminalKind::string, "", {}},
                 {"ID", TerminalKind::identifier, "", {}}};
  g.nonterminals = {"ACTION", "STEPS"};
  g.productions = {{0, {{true, 0}, {false, 1}, {true, 4}}, "animate", {"g.grammar", 7}}, {1, {}, "", {"g.grammar", 8}}};
  return g;
}

TEST(Grammar, FindsSymbolsByName) {
  const Grammar g = small_grammar();
  EXPECT_EQ(g.terminal_index("IntLit"), 2);
  EXPECT_EQ(g.terminal_index("Nope"), -1);
  EXPECT_EQ(g.nonterminal_index("STEPS"), 1);
  EXPECT_EQ(g.end_of_input(), 6);
}

TEST(Grammar, WritesProductionsForMessages) {
  const Grammar g = small_grammar();
  EXPECT_EQ(production_text(g, g.productions[0]), "<ACTION> ::= Animate <STEPS> StringLit => animate");
  EXPECT_EQ(production_text(g, g.productions[1]), "<STEPS> ::= (nothing)");
  EXPECT_EQ(location_text(g.productions[0].where), "g.grammar:7");
  EXPECT_EQ(format_grammar_error({{"g.grammar", 3}, "bad"}), "g.grammar:3: bad");
  EXPECT_EQ(format_grammar_error({{"g.grammar", 0}, "bad"}), "g.grammar: bad");
}

TEST(Grammar, DescribesTerminalsAsAPersonTypesThem) {
  const Grammar g = small_grammar();
  EXPECT_EQ(describe_terminal(g, 0), "'Animate'");
  EXPECT_EQ(describe_terminal(g, 1), "'['");
  EXPECT_EQ(describe_terminal(g, 2), "an integer");
  EXPECT_EQ(describe_terminal(g, 3), "a decimal number");
  EXPECT_EQ(describe_terminal(g, 4), "a \"string\"");
  EXPECT_EQ(describe_terminal(g, 5), "a name");
  EXPECT_EQ(describe_terminal(g, g.end_of_input()), "end of file");
  EXPECT_TRUE(carries_data(TerminalKind::identifier));
  EXPECT_FALSE(carries_data(TerminalKind::symbol));
  EXPECT_EQ(terminal_kind_name(TerminalKind::real), "real");
}

}  // namespace
}  // namespace fw::script
