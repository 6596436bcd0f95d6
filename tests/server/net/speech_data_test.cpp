// The voice data served to the browser's read aloud (/speech/data/NAME):
// the names it answers, the files they are, and that no name reaches a
// file outside the data folder; then the same on the real server.
#include "speech_data.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "http_get.hpp"
#include "room_test_server.hpp"

namespace fw::server {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

class SpeechDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("speech_data_test_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    data_ = root_ / "espeak-ng-data";
    for (const char* table : {"phontab", "phonindex", "phondata", "intonations"}) write(data_ / table, table);
    write(data_ / "en_dict", "en dictionary");
    write(data_ / "phondata-manifest", "not served");
    write(data_ / "lang/gmw/en", "name English");
    write(data_ / "lang/gmw/en-US", "name English (America)");
    write(data_ / "lang/roa/pt-BR", "name Portuguese (Brazil)");
    write(root_ / "secret", "outside the data folder");
    voices_ = {{"en", "lang/gmw/en"}, {"en-gb", "lang/gmw/en"}, {"en-us", "lang/gmw/en-US"},
               {"pt-br", "lang/roa/pt-BR"}, {"xx", "../secret"}, {"yy", (root_ / "secret").string()},
               {"zz", "lang/../../secret"}, {"EN", "lang/gmw/en"}, {"fr", "lang/roa/fr"}};
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
  fs::path data_;
  std::map<std::string, std::string> voices_;  ///< as espeak-ng would give them, and some it never would
};

TEST_F(SpeechDataTest, ServesThePhonemeTablesDictionariesAndVoicesByCode) {
  const SpeechData data(data_, voices_);
  EXPECT_EQ(data.find("phontab"), data_ / "phontab");
  EXPECT_EQ(data.find("intonations"), data_ / "intonations");
  EXPECT_EQ(data.find("en_dict"), data_ / "en_dict");
  EXPECT_EQ(data.find("lang/en"), data_ / "lang/gmw/en");
  EXPECT_EQ(data.find("lang/en-us"), data_ / "lang/gmw/en-US");
  EXPECT_EQ(data.find("lang/en-gb"), data_ / "lang/gmw/en");  // a code said by a voice of another name
  EXPECT_EQ(data.find("lang/pt-br"), data_ / "lang/roa/pt-BR");
}

TEST_F(SpeechDataTest, RefusesEveryNameOfAnotherShapeAndEveryPathOutside) {
  const SpeechData data(data_, voices_);
  for (const char* name : {"", "../secret", "../../etc/passwd", "/etc/passwd", "phontab/../../secret",
                           "lang/../../secret", "lang/gmw/en", "lang/en-US", "lang/EN", "lang/", "lang/xx", "lang/yy",
                           "lang/zz", "lang/fr",
                           "phondata-manifest", "de_dict", "EN_dict", "e_dict", "lang/-en", "lang/en/../en",
                           "lang/aaaaaaaaaaaaaaaaa", "phontab\n", "./phontab", "voices/!v/m1"})
    EXPECT_FALSE(data.find(name)) << "'" << name << "' was served";
  EXPECT_NE(SpeechData::refusal("../secret").find("GET /api/languages"), std::string::npos);
}

TEST_F(SpeechDataTest, AMissingFolderServesNothing) {
  EXPECT_FALSE(SpeechData(root_ / "nowhere", voices_).find("phontab"));
  EXPECT_FALSE(SpeechData(fs::path(), voices_).find("lang/en"));
}

TEST(SpeechDataServer, TheServerServesItsOwnEspeakDataAndNothingOutside) {
  test::RunningServer server;
  const auto phontab = test::http_get(server.http_port(), "/speech/data/phontab");
  ASSERT_EQ(phontab.status, 200) << phontab.body;
  EXPECT_GT(phontab.body.size(), 1000u);
  EXPECT_NE(phontab.headers.find("application/octet-stream"), std::string::npos);
  EXPECT_EQ(test::http_get(server.http_port(), "/speech/data/lang/en").status, 200);
  EXPECT_EQ(test::http_get(server.http_port(), "/speech/data/lang/pt-br").status, 200);
  EXPECT_EQ(test::http_get(server.http_port(), "/speech/data/lang/en-gb").status, 200);
  EXPECT_EQ(test::http_get(server.http_port(), "/speech/data/en_dict").status, 200);
  for (const char* path : {"/speech/data/../../../etc/passwd", "/speech/data/%2e%2e/%2e%2e/etc/passwd",
                           "/speech/data//etc/passwd", "/speech/data/lang/../../../../etc/passwd"}) {
    const auto reply = test::http_get(server.http_port(), path);
    EXPECT_EQ(reply.status, 404) << path;
    EXPECT_EQ(reply.body.find("root:"), std::string::npos) << path;
  }
  EXPECT_NE(test::http_get(server.http_port(), "/speech/data/nope").body.find("/api/languages"), std::string::npos);
}

}  // namespace
}  // namespace fw::server
