#include "fw/script/grammar_reader.hpp"

#include <map>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace fw::script {
namespace {

using test::joined;

bool read(const std::string& text, Grammar& grammar, std::vector<GrammarError>& errors,
          const GrammarResolver& resolve = {}) {
  return read_grammar({"t.grammar", text}, resolve, grammar, errors);
}

// True if some error is on `line` and mentions every one of `words`.
bool has_error(const std::vector<GrammarError>& errors, int line, std::initializer_list<std::string> words) {
  for (const GrammarError& e : errors) {
    if (line >= 0 && e.where.line != line) continue;
    bool all = true;
    for (const std::string& w : words) all = all && e.message.find(w) != std::string::npos;
    if (all) return true;
  }
  return false;
}

TEST(GrammarReader, ReadsThePapersGrammarAsPrinted) {
  Grammar g;
  std::vector<GrammarError> errors;
  ASSERT_TRUE(read(test::read_source("tests/behavior/script/data/paper_expression.grammar"), g, errors)) << joined(errors);
  // Its token classes are known by name, the repeated ')' is harmless.
  EXPECT_EQ(g.terminals.size(), 11u);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("IntLit"))].kind, TerminalKind::integer);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("Reallit"))].kind, TerminalKind::real);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("StringLit"))].kind, TerminalKind::string);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("ID"))].kind, TerminalKind::identifier);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("ClearAllFrame"))].kind, TerminalKind::keyword);
  EXPECT_EQ(g.terminals[static_cast<std::size_t>(g.terminal_index("("))].kind, TerminalKind::symbol);
  EXPECT_EQ(g.productions.size(), 15u);
  EXPECT_EQ(g.nonterminals[static_cast<std::size_t>(g.start)], "START");
  EXPECT_TRUE(g.productions[2].rhs.empty()) << "<ACTIONS> ::= derives nothing";
  EXPECT_EQ(g.productions[0].where.line, 15);
}

TEST(GrammarReader, ReadsKindsSpellingsRoutinesAndScannerOptions) {
  Grammar g;
  std::vector<GrammarError> errors;
  ASSERT_TRUE(read(R"(# a comment
#Scanner
comment //
keywords case-insensitive
#Terminal
Open   symbol [
Done   keyword fin
N      integer
#Production
<S> ::= Open <X> Done   => end_animation
<X> ::= N
#End
anything after #End is ignored
)",
                   g, errors))
      << joined(errors);
  EXPECT_EQ(g.scanner.comment_introducers, std::vector<std::string>{"//"});
  EXPECT_TRUE(g.scanner.keywords_ignore_case);
  EXPECT_EQ(g.terminals[1].spelling, "fin");
  EXPECT_EQ(g.terminals[0].spelling, "[");
  EXPECT_EQ(g.productions[0].routine, "end_animation");
  EXPECT_TRUE(g.productions[1].routine.empty());
}

TEST(GrammarReader, NamesUndeclaredAndUndefinedSymbols) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read("#Terminal\nend\n#Production\n<S> ::= <A> endd\n<S> ::= <B> end\n<A> ::= end\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 4, {"'endd'", "not declared under #Terminal"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 5, {"<B>", "no production defines it"})) << joined(errors);
}

TEST(GrammarReader, WantsAnEndAndKnownSections) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read("#Terminal\nend\n#Production\n<S> ::= end\n", g, errors));
  EXPECT_TRUE(has_error(errors, -1, {"no #End"})) << joined(errors);
  EXPECT_FALSE(read("#Terminals\nend\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 1, {"unknown section #Terminals"})) << joined(errors);
  EXPECT_FALSE(read("end\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 1, {"outside any section"})) << joined(errors);
  EXPECT_FALSE(read("#Terminal\n#Production\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 0, {"no productions"})) << joined(errors);
}

TEST(GrammarReader, RejectsMalformedLines) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read("#Terminal\nx blob\n<A>\nAU-1 keyword\n#Production\n<S> x\n<S> ::= x => a b\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 2, {"unknown terminal kind 'blob'"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 3, {"cannot name a terminal"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 4, {"keyword 'AU-1'"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 6, {"<NAME> ::="})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 7, {"one routine name"})) << joined(errors);
}

TEST(GrammarReader, TerminalsMustBeTellableApart) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read(R"(#Scanner
comment --
#Terminal
A keyword go
B keyword go
N integer
M integer
Dash symbol --
#Production
<S> ::= A B N M Dash
#End
)",
                    g, errors));
  EXPECT_TRUE(has_error(errors, 5, {"A and B", "'go'"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 7, {"N and M", "integer"})) << joined(errors);
  EXPECT_TRUE(has_error(errors, 8, {"comment introducer"})) << joined(errors);
}

TEST(GrammarReader, KeywordsThatDifferOnlyInCaseClashWhenCaseIsIgnored) {
  Grammar g;
  std::vector<GrammarError> errors;
  const std::string terminals = "#Terminal\nA keyword Go\nB keyword go\n#Production\n<S> ::= A B\n#End\n";
  EXPECT_TRUE(read(terminals, g, errors)) << joined(errors);
  EXPECT_FALSE(read("#Scanner\nkeywords case-insensitive\n" + terminals, g, errors));
}

TEST(GrammarReader, IncludesMergeAndTheTopFileNamesTheStart) {
  const std::map<std::string, std::string> files = {
      {"a.grammar", "#Terminal\nend\nIntLit\n#Production\n<A> ::= IntLit end\n<N> ::= IntLit\n#End\n"},
      {"b.grammar", "#Terminal\nend\nGo\nIntLit\n#Production\n<B> ::= Go end\n<N> ::= IntLit\n#End\n"},
  };
  const GrammarResolver resolve = [&](const std::string&, const std::string& name) -> std::optional<GrammarSource> {
    const auto at = files.find(name);
    if (at == files.end()) return std::nullopt;
    return GrammarSource{name, at->second};
  };
  Grammar g;
  std::vector<GrammarError> errors;
  ASSERT_TRUE(read("#Include a.grammar\n#Include b.grammar\n#Production\n<S> ::= <A>\n<S> ::= <B>\n#End\n", g, errors,
                   resolve))
      << joined(errors);
  EXPECT_EQ(g.nonterminals[static_cast<std::size_t>(g.start)], "S");
  EXPECT_EQ(g.terminals.size(), 3u) << "end and IntLit are shared";
  EXPECT_EQ(g.productions.size(), 5u) << "the repeated <N> ::= IntLit is kept once";

  EXPECT_FALSE(read("#Include missing.grammar\n#Production\n<S> ::= <A>\n#End\n", g, errors, resolve));
  EXPECT_TRUE(has_error(errors, 1, {"cannot find the included grammar 'missing.grammar'"})) << joined(errors);
}

TEST(GrammarReader, AFileIncludingItselfStops) {
  const GrammarResolver resolve = [](const std::string&, const std::string& name) -> std::optional<GrammarSource> {
    return GrammarSource{name, "#Include self.grammar\n#Terminal\nx\n#Production\n<S> ::= x\n#End\n"};
  };
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read("#Include self.grammar\n#End\n", g, errors, resolve));
  EXPECT_TRUE(has_error(errors, -1, {"nest deeper"})) << joined(errors);
}

TEST(GrammarReader, ARepeatedProductionWithAnotherRoutineIsAContradiction) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read("#Terminal\nx\n#Production\n<S> ::= x => animate\n<S> ::= x => hold\n#End\n", g, errors));
  EXPECT_TRUE(has_error(errors, 5, {"t.grammar:4", "another routine"})) << joined(errors);
}

TEST(GrammarReader, OversizedGrammarsAreRefused) {
  Grammar g;
  std::vector<GrammarError> errors;
  EXPECT_FALSE(read(std::string(kMaxGrammarBytes + 1, '\n'), g, errors));
  EXPECT_TRUE(has_error(errors, 0, {"bytes"})) << joined(errors);
}

}  // namespace
}  // namespace fw::script
