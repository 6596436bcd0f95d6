#include "fw/script/semantic_handler.hpp"

#include <gtest/gtest.h>

#include "fw/script/parser.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::joined;

// Routines that record what they were given.
std::vector<std::vector<SemanticValue>> calls;

SemanticValue item(RoutineCall& call) {
  calls.emplace_back(call.values.begin(), call.values.end());
  if (call.values[0].text == "bad") call.diagnostics.error(call.values[0].position, "bad item");
  return {};
}

SemanticValue close(RoutineCall& call) {
  call.script.meaning.emotions.emplace_back();  // something to roll back
  calls.push_back({});
  return {};
}

SemanticValue twice(RoutineCall& call) { return SemanticValue::of_integer(call.values[0].integer * 2, call.position); }

const Language& items_language() {
  static const Language language = [] {
    RoutineLibrary library;
    library.add({"item", {{kTextParameter, "name"}, {kIntegerParameter | kOptional, "count"}}, ValueKind::none, item, ""});
    library.add({"close", {}, ValueKind::none, close, ""});
    library.add({"twice", {{kIntegerParameter, "n"}}, ValueKind::integer, twice, ""});
    std::vector<GrammarError> errors;
    auto loaded = load_language({"items.grammar", R"(#Terminal
[
]
(
)
x
IntLit
ID
#Production
<S>     ::= [ <ITEMS> ]   => close
<ITEMS> ::= <ITEM> <ITEMS>
<ITEMS> ::=
<ITEM>  ::= ID <N>        => item
<N>     ::= IntLit
<N>     ::= ( <N> )
<N>     ::= <DOUBLED>
<N>     ::=
<DOUBLED> ::= x IntLit    => twice
#End
)"},
                                {}, library, errors);
    EXPECT_TRUE(loaded) << joined(errors);
    return std::move(*loaded);
  }();
  return language;
}

int production(const Language& language, const std::string& text) {
  for (std::size_t p = 0; p < language.grammar.productions.size(); ++p)
    if (production_text(language.grammar, language.grammar.productions[p]) == text) return static_cast<int>(p);
  ADD_FAILURE() << "no production " << text;
  return 0;
}

TEST(SemanticHandler, HandsARoutineTheValuesOfItsSymbols) {
  const Language& language = items_language();
  ScriptBuilder script;
  DiagnosticList diagnostics;
  SemanticHandler handler(language, script, diagnostics);
  calls.clear();
  handler.begin_sentence();
  const int item_production = production(language, "<ITEM> ::= ID <N> => item");
  const auto expansion = handler.expand(item_production, false, {1, 1});
  EXPECT_TRUE(expansion.complete_later);
  EXPECT_TRUE(expansion.children_wanted);
  Token name;
  name.value = SemanticValue::of_text("a", {1, 1});
  handler.shift(name, true);
  // <N> ::= IntLit hands its value straight up: no marker.
  const auto pass = handler.expand(production(language, "<N> ::= IntLit"), true, {1, 3});
  EXPECT_FALSE(pass.complete_later);
  EXPECT_TRUE(pass.children_wanted);
  Token count;
  count.value = SemanticValue::of_integer(7, {1, 3});
  handler.shift(count, true);
  handler.complete(item_production, false, {1, 1});
  ASSERT_EQ(calls.size(), 1u);
  ASSERT_EQ(calls[0].size(), 2u);
  EXPECT_EQ(calls[0][0].text, "a");
  EXPECT_EQ(calls[0][1].integer, 7);

  // <N> ::= (nothing) fills its slot with no value.
  handler.expand(item_production, false, {2, 1});
  handler.shift(name, true);
  const auto empty = handler.expand(production(language, "<N> ::= (nothing)"), true, {2, 3});
  EXPECT_FALSE(empty.complete_later);
  EXPECT_FALSE(empty.children_wanted);
  handler.complete(item_production, false, {2, 1});
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[1][1].kind, ValueKind::none);
  EXPECT_EQ(calls[1][1].position, (SourcePosition{2, 3}));
}

TEST(SemanticHandler, ValuesFlowThroughNestedProductionsAndRoutineResults) {
  calls.clear();
  const ScriptResult result = parse_script(items_language(), "[a 1 b (2) c ((x 21)) d]");
  EXPECT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(calls.size(), 5u);
  EXPECT_EQ(calls[0][1].integer, 1);
  EXPECT_EQ(calls[1][1].kind, ValueKind::none) << "( <N> ) has no routine and more than one symbol: no value";
  EXPECT_EQ(calls[2][1].kind, ValueKind::none);
  EXPECT_EQ(calls[3][0].text, "d");
  EXPECT_EQ(calls[3][1].kind, ValueKind::none);
  EXPECT_EQ(result.meaning.emotions.size(), 1u);
}

TEST(SemanticHandler, ARoutineResultIsTheProductionsValue) {
  calls.clear();
  const ScriptResult result = parse_script(items_language(), "[a x 21]");
  EXPECT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0][1].integer, 42);
}

TEST(SemanticHandler, ASentenceWithARoutineErrorIsDroppedWhole) {
  calls.clear();
  const ScriptResult result = parse_script(items_language(), "[a 1] [bad 2] [c]");
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.sentences, 3u);
  EXPECT_EQ(result.meaning.emotions.size(), 2u) << "the sentences before and after survive";
  ASSERT_EQ(test::errors_of(result).size(), 1u);
  EXPECT_EQ(test::errors_of(result)[0].position, (SourcePosition{1, 8}));
}

}  // namespace
}  // namespace fw::script
