#include "chat_script.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

TEST(ChatScript, TimedLinesAndLinesThatFollow) {
  std::vector<ScriptedLine> lines;
  std::string error;
  ASSERT_TRUE(parse_chat_script("# a conversation\n1.5 hello everyone\nhow are you?\n\n10 I have to go\r\nbye", lines,
                                error))
      << error;
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_DOUBLE_EQ(lines[0].at_s, 1.5);
  EXPECT_EQ(lines[0].text, "hello everyone");
  EXPECT_DOUBLE_EQ(lines[1].at_s, 1.5 + kDefaultGapS);
  EXPECT_EQ(lines[1].text, "how are you?");
  EXPECT_DOUBLE_EQ(lines[2].at_s, 10);
  EXPECT_EQ(lines[2].text, "I have to go");
  EXPECT_DOUBLE_EQ(lines[3].at_s, 12);
}

TEST(ChatScript, TextThatStartsLikeANumberIsText) {
  std::vector<ScriptedLine> lines;
  std::string error;
  ASSERT_TRUE(parse_chat_script("3 2 cats\n2nd try\n42\n", lines, error)) << error;
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "2 cats");
  EXPECT_EQ(lines[1].text, "2nd try");
  EXPECT_EQ(lines[2].text, "42");
}

TEST(ChatScript, LinesAreSentInTheOrderOfTheirTimes) {
  std::vector<ScriptedLine> lines;
  std::string error;
  ASSERT_TRUE(parse_chat_script("5 later\n1 sooner\n", lines, error)) << error;
  EXPECT_EQ(lines[0].text, "sooner");
  EXPECT_EQ(lines[1].text, "later");
}

TEST(ChatScript, AMistakeNamesItsLineAndWhatToDo) {
  std::vector<ScriptedLine> lines;
  std::string error;
  EXPECT_FALSE(parse_chat_script("hi\n2 " + std::string(codec::kMaxChatBytes + 1, 'a'), lines, error));
  EXPECT_NE(error.find("line 2: a chat line holds at most 500 bytes"), std::string::npos) << error;
  EXPECT_FALSE(parse_chat_script("9999999 too late", lines, error));
  EXPECT_NE(error.find("line 1: the time must be"), std::string::npos) << error;
  EXPECT_FALSE(parse_chat_script("1.5 ", lines, error));
  EXPECT_NE(error.find("no text"), std::string::npos) << error;
}

TEST(ChatScript, AFileTooLargeOrMissingIsRefused) {
  std::vector<ScriptedLine> lines;
  std::string error;
  EXPECT_FALSE(read_chat_script("/nonexistent/chat.txt", lines, error));
  EXPECT_NE(error.find("cannot read"), std::string::npos);
  const auto path = std::filesystem::temp_directory_path() / ("chat-script-" + std::to_string(::getpid()));
  {
    std::ofstream big(path);
    for (std::size_t i = 0; i < kMaxChatScriptBytes / 10 + 1; ++i) big << "123456789\n";
  }
  EXPECT_FALSE(read_chat_script(path.string(), lines, error));
  EXPECT_NE(error.find("larger than 1 MB"), std::string::npos) << error;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fw::client
