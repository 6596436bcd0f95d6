#include "script_command.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "run_command.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

std::string source(const std::string& relative) { return fw::test::source_path(relative); }
std::string server() { return test::bin("facewire-server"); }

// stdout alone: warnings on stderr are dropped inside the group.
test::CommandResult run_stdout(const std::string& arguments) {
  return test::run_command("{ " + server() + " " + arguments + " 2>/dev/null; }");
}

TEST(ScriptCommand, RegistersTheSubcommand) {
  CLI::App app;
  add_script_command(app);
  CLI::App* script = app.get_subcommand("script");
  ASSERT_NE(script, nullptr);
  EXPECT_NE(script->get_option("--grammar"), nullptr);
  EXPECT_TRUE(script->get_option("file")->get_required());
}

TEST(ScriptCommand, PrintsTheMeaningOfAGoodFileAsJson) {
  const std::string anger = source("avatar/behavior/script/examples/anger.fws");
  const auto result = run_stdout("script " + anger);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(result.output.front(), '{');
  for (const char* expected : {"\"animations\": [", "\"start\": \"neutral\"", "\"au\": 4", "\"intensity\": 2.0",
                               "\"face_intensity\": 1.0", "\"shading\": \"SmoothShading\"", "\"carried\": false"})
    EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
  // The warning about AU 42 goes to stderr, in FILE:LINE:COLUMN form.
  const auto both = test::run_command(server() + " script " + anger);
  EXPECT_NE(both.output.find(anger + ":16:2: warning: AU 42 (slit)"), std::string::npos) << both.output;
}

TEST(ScriptCommand, ReportsEachErrorOnALineAndExitsWith2) {
  const std::string bad = source("tests/behavior/script/data/bad_sentences.fws");
  const auto result = test::run_command(server() + " script " + bad);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find(bad + ":5:5: expected an integer or a decimal number, found the name 'strong'\n"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(bad + ":8:29: AU 3 is not a FACS action unit"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find('{'), std::string::npos) << "no JSON when there are errors";
}

TEST(ScriptCommand, TakesAnotherGrammar) {
  const auto dir = std::filesystem::temp_directory_path() / ("fw_script_cmd_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "wave.fws") << "clear key 12:1 hold 5 play 3 done\n";
  const auto result =
      run_stdout("script --grammar " + source("tests/behavior/script/data/expression_hold.grammar") + " " +
                 (dir / "wave.fws").string());
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("\"kind\": \"hold\""), std::string::npos) << result.output;

  // A grammar that is not LL(1) is refused with the conflict named.
  const auto refused = test::run_command(server() + " script --grammar " +
                                         source("tests/behavior/script/data/not_ll1.grammar") + " " +
                                         (dir / "wave.fws").string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.output.find("not_ll1.grammar:11: the grammar is not LL(1)"), std::string::npos) << refused.output;
  std::filesystem::remove_all(dir);
}

TEST(ScriptCommand, AMissingFileIsExplained) {
  const auto result = test::run_command(server() + " script /no/such/script.fws");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("/no/such/script.fws: no such file"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace fw::server
