#include "fw/script/grammar_sources.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "fw/script/parser.hpp"
#include "fw/script/standard_routines.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::joined;

TEST(GrammarSources, TheCompiledInGrammarsAreTheFilesInGrammars) {
  ASSERT_EQ(builtin_grammar_names().size(), 4u);
  for (std::string_view name : builtin_grammar_names()) {
    const auto source = builtin_grammar(name);
    ASSERT_TRUE(source) << name;
    EXPECT_EQ(source->text, test::read_source("avatar/behavior/script/grammars/" + std::string(name))) << name;
  }
  EXPECT_FALSE(builtin_grammar("nope.grammar"));
  EXPECT_EQ(builtin_grammar("facewire.grammar")->name, "<builtin>/facewire.grammar");
}

TEST(GrammarSources, EveryShippedGrammarLoadsOnItsOwn) {
  for (std::string_view name : builtin_grammar_names()) {
    std::vector<GrammarError> errors;
    EXPECT_TRUE(load_language(*builtin_grammar(name), builtin_resolver(), standard_routines(), errors))
        << name << "\n"
        << joined(errors);
  }
}

TEST(GrammarSources, TheDefaultLanguageReadsEveryExampleInOneScript) {
  std::string all;
  for (const char* example : {"anger.fws", "au1.fws", "blushing.fws"})
    all += test::read_source(std::string("avatar/behavior/script/examples/") + example) + "\n";
  const ScriptResult result = parse_script(default_language(), all);
  EXPECT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_EQ(result.sentences, 6u);
  EXPECT_EQ(result.meaning.animations.size(), 1u);
  EXPECT_EQ(result.meaning.au_definitions.size(), 1u);
  EXPECT_EQ(result.meaning.vascular_expressions.size(), 3u);
  EXPECT_EQ(result.meaning.emotions.size(), 1u);
}

TEST(GrammarSources, FilesIncludeTheirNeighboursOrElseShippedGrammars) {
  const auto dir = std::filesystem::temp_directory_path() / ("fw_script_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "mine.grammar") << "#Include extra.grammar\n#Include vascular.grammar\n#Production\n"
                                         "<S> ::= <EXTRA>\n<S> ::= <VASCULAR_SENTENCE>\n#End\n";
  std::ofstream(dir / "extra.grammar") << "#Terminal\nwave\n#Production\n<EXTRA> ::= wave\n#End\n";
  std::string error;
  const auto source = read_grammar_file((dir / "mine.grammar").string(), error);
  ASSERT_TRUE(source) << error;
  std::vector<GrammarError> errors;
  const auto language = load_language(*source, file_resolver(), standard_routines(), errors);
  ASSERT_TRUE(language) << joined(errors);
  EXPECT_TRUE(parse_script(*language, "wave [expression e [mpca nose intensity 1]] wave").ok());

  // Shipped grammars include shipped grammars, whatever lies beside the file.
  std::ofstream(dir / "expression.grammar") << "not a grammar";
  const auto shipped = file_resolver()("<builtin>/facewire.grammar", "expression.grammar");
  ASSERT_TRUE(shipped);
  EXPECT_EQ(shipped->name, "<builtin>/expression.grammar");
  EXPECT_EQ(file_resolver()((dir / "mine.grammar").string(), "expression.grammar")->text, "not a grammar");

  EXPECT_FALSE(read_grammar_file((dir / "missing.grammar").string(), error));
  EXPECT_NE(error.find("no such file"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fw::script
