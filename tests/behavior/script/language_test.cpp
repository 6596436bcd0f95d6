#include "fw/script/language.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace fw::script {
namespace {

using test::joined;
using test::language_from;

TEST(Language, BindsRoutinesAndWorksOutWhichSymbolsGiveValues) {
  std::vector<GrammarError> errors;
  const auto language = language_from(test::read_source("avatar/behavior/script/grammars/expression.grammar"), errors);
  ASSERT_TRUE(language) << joined(errors);
  const Grammar& g = language->grammar;
  const auto production = [&](const std::string& text) {
    for (std::size_t p = 0; p < g.productions.size(); ++p)
      if (production_text(g, g.productions[p]) == text) return p;
    ADD_FAILURE() << "no production " << text;
    return std::size_t{0};
  };
  const std::size_t au_head = production("<AUHEAD> ::= <AUID> <STRENGTH> => au_intensity");
  ASSERT_TRUE(language->routines[au_head]);
  EXPECT_EQ(language->routines[au_head]->name, "au_intensity");
  EXPECT_EQ(language->value_slots[au_head], 2);
  EXPECT_EQ(language->value_slots[production("<ACTION> ::= Animate <STEPS> <SHADING> => animate")], 2);
  EXPECT_FALSE(language->routines[production("<ACTIONS> ::= <ACTION> <ACTIONS>")]);
  EXPECT_TRUE(language->gives({false, g.nonterminal_index("AUID")}));
  EXPECT_TRUE(language->gives({false, g.nonterminal_index("STRENGTH")}));
  EXPECT_FALSE(language->gives({false, g.nonterminal_index("AULIST")}));
  EXPECT_FALSE(language->gives({true, g.terminal_index("Animate")}));
  EXPECT_TRUE(language->gives({true, g.terminal_index("IntLit")}));
  EXPECT_EQ(language->finishes.size(), 1u) << "the vascular colour resolution";
}

TEST(Language, BracketsAreKnownForErrorRecovery) {
  std::vector<GrammarError> errors;
  const auto language = language_from(test::read_source("avatar/behavior/script/grammars/vascular.grammar"), errors);
  ASSERT_TRUE(language) << joined(errors);
  EXPECT_EQ(language->bracket_delta[static_cast<std::size_t>(language->grammar.terminal_index("["))], 1);
  EXPECT_EQ(language->bracket_delta[static_cast<std::size_t>(language->grammar.terminal_index("]"))], -1);
  EXPECT_EQ(language->bracket_delta[static_cast<std::size_t>(language->grammar.terminal_index("%"))], 0);
}

TEST(Language, AnUnknownRoutineIsNamedWithTheLibrarysRoutines) {
  std::vector<GrammarError> errors;
  EXPECT_FALSE(language_from("#Terminal\nx\n#Production\n<S> ::= x => begin_keyfram\n#End\n", errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].where.line, 4);
  EXPECT_NE(errors[0].message.find("'begin_keyfram' is not in the routine library"), std::string::npos);
  EXPECT_NE(errors[0].message.find("begin_keyframe"), std::string::npos) << "the known ones are listed";
}

TEST(Language, ARoutineMustGetAsManyValuesAsItTakes) {
  std::vector<GrammarError> errors;
  EXPECT_FALSE(language_from("#Terminal\nIntLit\n#Production\n<S> ::= IntLit => au_intensity\n#End\n", errors));
  ASSERT_EQ(errors.size(), 1u) << joined(errors);
  EXPECT_NE(errors[0].message.find("gives 1 value(s): IntLit (an integer); but au_intensity takes 2"),
            std::string::npos)
      << errors[0].message;
}

TEST(Language, ARoutineMustGetValuesOfTheKindsItTakes) {
  std::vector<GrammarError> errors;
  EXPECT_FALSE(language_from("#Terminal\nID\nStringLit\n#Production\n<S> ::= ID <N> => au_intensity\n<N> ::= StringLit\n#End\n",
                             errors));
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(joined(errors).find("au_intensity takes the action-unit number as value 1, which must be an integer, but ID can give a text"),
            std::string::npos)
      << joined(errors);
  EXPECT_NE(joined(errors).find("<N> can give a text"), std::string::npos) << joined(errors);
}

TEST(Language, AnOptionalValueMayBeMissing) {
  // animate's shading is optional: <SHADING> may give a string or nothing.
  std::vector<GrammarError> errors;
  const auto language = language_from(test::read_source("tests/behavior/script/data/expression_hold.grammar"), errors);
  EXPECT_TRUE(language) << joined(errors);
}

TEST(Language, AGrammarErrorStopsTheLoad) {
  std::vector<GrammarError> errors;
  EXPECT_FALSE(language_from(test::read_source("tests/behavior/script/data/not_ll1.grammar"), errors));
  EXPECT_NE(joined(errors).find("not LL(1)"), std::string::npos);
}

}  // namespace
}  // namespace fw::script
