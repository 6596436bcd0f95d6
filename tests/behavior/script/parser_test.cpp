#include "fw/script/parser.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/limits.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::errors_of;
using test::joined;

ScriptResult parse_default(std::string_view text) { return parse_script(default_language(), text); }

TEST(Parser, AMalformedSentenceGivesLineColumnExpectedAndFound) {
  const ScriptResult result = parse_default("ClearAllFrame\nBeginKeyFrame\n  4 strong\nend\n");
  const auto errors = errors_of(result);
  ASSERT_EQ(errors.size(), 1u) << joined(result.diagnostics);
  EXPECT_EQ(errors[0].position, (SourcePosition{3, 5}));
  EXPECT_EQ(errors[0].message, "expected an integer or a decimal number, found the name 'strong'");
  EXPECT_TRUE(result.meaning.animations.empty());
}

TEST(Parser, ExpectedListsEverythingThatCouldComeNext) {
  // After a keyframe's AU pair: another AU, another keyframe, Animate or end.
  const auto errors = errors_of(parse_default("ClearAllFrame BeginKeyFrame 4 1.0 \"x\" end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 35}));
  EXPECT_EQ(errors[0].message, "expected 'end', 'BeginKeyFrame', 'Animate' or an integer, found the string \"x\"");
}

TEST(Parser, AnUnfinishedSentenceSaysWhereItStarted) {
  const auto errors = errors_of(parse_default("\nClearAllFrame BeginKeyFrame 2 1.0\n"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].position, (SourcePosition{3, 1}));
  EXPECT_NE(errors[0].message.find("found end of file (the sentence that starts at 2:1 is not finished)"),
            std::string::npos)
      << errors[0].message;
}

TEST(Parser, ScanErrorsAreReportedWithWhatWasExpected) {
  const auto errors = errors_of(parse_default("ClearAllFrame BeginKeyFrame 2 @ end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 31}));
  EXPECT_EQ(errors[0].message, "unexpected character '@'; expected an integer or a decimal number here");
}

TEST(Parser, GarbageBeforeASentenceNamesWhatCanStartOne) {
  const auto errors = errors_of(parse_default("hello ClearAllFrame end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "expected 'ClearAllFrame', 'KeepAllFrame', 'AU' or '[', found the name 'hello'");
}

TEST(Parser, ParsingResumesAtTheNextSentence) {
  const ScriptResult result = parse_default(test::read_source("tests/behavior/script/data/bad_sentences.fws"));
  const auto errors = errors_of(result);
  ASSERT_EQ(errors.size(), 2u) << joined(result.diagnostics);
  EXPECT_EQ(errors[0].position, (SourcePosition{5, 5}));
  EXPECT_EQ(errors[1].position, (SourcePosition{8, 29}));
  EXPECT_NE(errors[1].message.find("AU 3 is not a FACS action unit"), std::string::npos);
  EXPECT_EQ(result.sentences, 4u);
  EXPECT_EQ(result.meaning.animations.size(), 1u) << "the good sentence before the errors";
  EXPECT_EQ(result.meaning.emotions.size(), 1u) << "the good sentence after them";
}

TEST(Parser, RecoveryInsideBracketsWaitsForThemToClose) {
  const ScriptResult result =
      parse_default("[emotion a [s1 duration oops [expression e intensity 1]]]\n[expression e [mpca nose intensity 0.5]]");
  const auto errors = errors_of(result);
  ASSERT_EQ(errors.size(), 1u) << joined(result.diagnostics);
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 25}));
  EXPECT_EQ(result.meaning.vascular_expressions.size(), 1u) << "the [ inside the broken emotion started nothing";
}

TEST(Parser, ManyErrorsStopAtTheLimit) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "ClearAllFrame BeginKeyFrame 3 1.0 end\n";
  const ScriptResult result = parse_default(text);
  EXPECT_EQ(result.diagnostics.size(), kMaxErrors);
  EXPECT_NE(result.diagnostics.back().message.find("too many errors"), std::string::npos);
  EXPECT_LT(result.sentences, 100u);
}

TEST(Parser, OversizedScriptsAreRefusedUnread) {
  const ScriptResult result = parse_default(std::string(kMaxScriptBytes + 1, ' '));
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_NE(result.diagnostics[0].message.find("split it"), std::string::npos);
}

TEST(Parser, DeepNestingIsAnErrorNotAStackOverflow) {
  std::vector<GrammarError> grammar_errors;
  const auto language = test::language_from("#Terminal\nx\n(\n)\n#Production\n<E> ::= ( <E> )\n<E> ::= x\n#End\n",
                                            grammar_errors);
  ASSERT_TRUE(language) << joined(grammar_errors);
  const std::string deep = std::string(100000, '(') + "x" + std::string(100000, ')');
  const ScriptResult result = parse_script(*language, deep);
  const auto errors = errors_of(result);
  ASSERT_EQ(errors.size(), 1u) << joined(result.diagnostics);
  EXPECT_NE(errors[0].message.find("nests too deeply"), std::string::npos);
  EXPECT_TRUE(parse_script(*language, "((((x))))").ok());
}

TEST(Parser, LongListsDoNotGrowTheStack) {
  std::string text = "ClearAllFrame\n";
  for (int i = 0; i < 900; ++i) text += "BeginKeyFrame 4 0.5 12 1.0\n";
  text += "end\n";
  const ScriptResult result = parse_default(text);
  EXPECT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(result.meaning.animations.size(), 1u);
  EXPECT_EQ(result.meaning.animations[0].keyframes.size(), 900u);
}

TEST(Parser, AnEmptyScriptSaysSo) {
  const ScriptResult result = parse_default("# only a comment\n");
  EXPECT_TRUE(result.ok());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].message, "the script holds no sentences");
}

// The "done when": a second grammar file, loaded at run time, and
// the same kernel parses its sentences.
TEST(Parser, ASecondGrammarChangesTheLanguageNotTheKernel) {
  std::vector<GrammarError> grammar_errors;
  const auto hold_language =
      test::language_from(test::read_source("tests/behavior/script/data/expression_hold.grammar"), grammar_errors);
  ASSERT_TRUE(hold_language) << joined(grammar_errors);
  const ScriptResult result = parse_script(*hold_language, "CLEAR key 4:2 12:0.5 // two AUs\nhold 3 play 5 \"Texture\"\nkey play 2 done");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(result.meaning.animations.size(), 1u);
  const KeyframeAnimation& a = result.meaning.animations[0];
  EXPECT_TRUE(a.clear_frames);
  ASSERT_EQ(a.keyframes.size(), 2u);
  ASSERT_EQ(a.keyframes[0].aus.size(), 2u);
  EXPECT_EQ(a.keyframes[0].aus[0].au, 4);
  EXPECT_DOUBLE_EQ(a.keyframes[0].aus[0].intensity, 2.0);
  EXPECT_DOUBLE_EQ(a.keyframes[0].aus[1].intensity, 0.5);
  ASSERT_EQ(a.plays.size(), 3u);
  EXPECT_EQ(a.plays[0].kind, PlayKind::hold);
  EXPECT_EQ(a.plays[0].steps, 3);
  EXPECT_EQ(a.plays[1].kind, PlayKind::animate);
  EXPECT_EQ(a.plays[1].shading, "Texture");
  EXPECT_EQ(a.plays[2].shading, "Texture") << "the shading is optional in this language";
  EXPECT_EQ(a.plays[2].keyframe_count, 2u);

  // The same text is no sentence of the default language, and the default
  // language's sentences are none of this one.
  EXPECT_FALSE(parse_default("clear key 4:2 done").ok());
  const auto errors = errors_of(parse_script(*hold_language, "ClearAllFrame BeginKeyFrame 4 1.0 end"));
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0].message, "'ClearAllFrame' is not a word of this language; expected 'clear' or 'keep' here");
}

// The paper's grammar as printed, without routines: it recognises the
// paper's anger sentence (its meaning needs routine bindings).
TEST(Parser, ThePapersOwnGrammarRecognisesThePapersSentence) {
  RoutineLibrary no_routines;
  std::vector<GrammarError> grammar_errors;
  const auto language = load_language(
      {"paper_expression.grammar", test::read_source("tests/behavior/script/data/paper_expression.grammar")}, {},
      no_routines, grammar_errors);
  ASSERT_TRUE(language) << joined(grammar_errors);
  const std::string anger = test::read_source("avatar/behavior/script/examples/anger.fws");
  const auto without_comments = anger.substr(anger.find("ClearAllFrame"));
  const ScriptResult result = parse_script(*language, without_comments);
  EXPECT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_EQ(result.sentences, 1u);
  EXPECT_TRUE(result.meaning.animations.empty());
  EXPECT_FALSE(parse_script(*language, "ClearAllFrame BeginKeyFrame 4 2 end").ok()) << "its strengths are reals";
}

}  // namespace
}  // namespace fw::script
