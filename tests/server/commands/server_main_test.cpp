// facewire-server, started for real on a loopback port and spoken to over
// sockets, and its command line as a person types it.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <vector>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "http_get.hpp"
#include "run_command.hpp"
#include "server_process.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using test::http_exchange;
using test::http_get;

std::string source_file(const std::string& path) {
  std::ifstream in(fw::test::source_path(path), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class ServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = new test::ServerProcess(test::bin("facewire-server"));
    ASSERT_GT(server_->port(), 0) << "the server did not start";
  }
  static void TearDownTestSuite() { delete server_; }
  static int port() { return server_->port(); }
  static inline test::ServerProcess* server_ = nullptr;
};

TEST_F(ServerTest, AnswersHealthChecks) {
  const auto reply = http_get(port(), "/healthz");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.body, "ok\n");
}

TEST_F(ServerTest, ServesThePage) {
  const auto reply = http_get(port(), "/");
  EXPECT_EQ(reply.status, 200);
  EXPECT_NE(reply.headers.find("text/html"), std::string::npos);
  EXPECT_EQ(reply.body, source_file("web/index.html"));
}

TEST_F(ServerTest, ServesTheSameAssetAndShadersAsTheNativeRenderer) {
  EXPECT_EQ(http_get(port(), "/generic_face.json").body, source_file("avatar/model/assets/generic_face.json"));
  EXPECT_EQ(http_get(port(), "/shaders/face.vert").body, source_file("avatar/render/shaders/face.vert"));
  EXPECT_EQ(http_get(port(), "/shaders/face.frag?v=1").body, source_file("avatar/render/shaders/face.frag"));
}

TEST_F(ServerTest, RevalidatesWithETag) {
  const auto first = http_get(port(), "/generic_face.json");
  const auto at = first.headers.find("ETag: ");
  ASSERT_NE(at, std::string::npos) << first.headers;
  const std::string etag = first.headers.substr(at + 6, first.headers.find("\r\n", at) - at - 6);
  const auto second = http_get(port(), "/generic_face.json", "If-None-Match: " + etag + "\r\n");
  EXPECT_EQ(second.status, 304);
  EXPECT_TRUE(second.body.empty());
}

TEST_F(ServerTest, UnknownPathIsNotFound) {
  const auto reply = http_get(port(), "/secret");
  EXPECT_EQ(reply.status, 404);
  EXPECT_NE(reply.body.find("nothing at /secret"), std::string::npos);
}

TEST_F(ServerTest, OnlyReadsAreAllowed) {
  const auto reply = http_exchange(port(), "DELETE / HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(reply.status, 405);
  EXPECT_NE(reply.headers.find("Allow: GET, HEAD"), std::string::npos);
}

TEST_F(ServerTest, MalformedRequestClosesOnlyThatConnection) {
  const auto reply = http_exchange(port(), "THIS IS NOT HTTP\r\n\r\n");
  EXPECT_EQ(reply.status, 400);
  EXPECT_NE(reply.body.find("malformed HTTP request"), std::string::npos) << reply.body;
  EXPECT_EQ(http_get(port(), "/healthz").status, 200) << "the server goes on";
}

TEST_F(ServerTest, OversizedHeadersAreRefused) {
  const auto reply = http_get(port(), "/healthz", "X-Padding: " + std::string(10000, 'a') + "\r\n");
  EXPECT_EQ(reply.status, 431);
  EXPECT_NE(reply.body.find("8 KiB"), std::string::npos);
}

TEST_F(ServerTest, OversizedBodyIsRefused) {
  const auto reply = http_exchange(
      port(), "GET / HTTP/1.1\r\nHost: x\r\nContent-Length: 1000000\r\nConnection: close\r\n\r\n" + std::string(70000, 'x'));
  EXPECT_EQ(reply.status, 413);
}

TEST(ServerProcess, StopsCleanlyOnSigterm) {
  test::ServerProcess server(test::bin("facewire-server"));
  ASSERT_GT(server.port(), 0);
  EXPECT_EQ(http_get(server.port(), "/healthz").status, 200);
  EXPECT_EQ(server.terminate(10000), 0);
}

TEST(ServerCli, BadEndpointIsExplained) {
  const auto result = test::run_command(test::bin("facewire-server") + " serve --http localhost");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("write it like 127.0.0.1:8080"), std::string::npos) << result.output;
}

TEST(ServerCli, PortInUseIsExplained) {
  test::ServerProcess first(test::bin("facewire-server"));
  ASSERT_GT(first.port(), 0);
  const auto result = test::run_command(test::bin("facewire-server") + " serve --http 127.0.0.1:" +
                                        std::to_string(first.port()));
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("cannot listen on"), std::string::npos) << result.output;
}

TEST(ServerCli, TokenNeedsASecret) {
  const auto result = test::run_command("env -u FACEWIRE_AUTH_SECRET " + test::bin("facewire-server") + " token --room a --name Ann");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--auth-secret"), std::string::npos) << result.output;
}

TEST(ServerCli, TokenIsMinted) {
  const auto result =
      test::run_command(test::bin("facewire-server") + " token --room a --name Ann --ttl 60 --auth-secret s3cret");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(result.output.rfind("fw1.", 0), 0u) << result.output;
}

// --- the command line ------------------------------------------------------

std::string server_command(const std::string& arguments) { return test::bin("facewire-server") + " " + arguments; }

/// The first line `fd` delivers within `timeout_ms`.
std::string first_line(int fd, int timeout_ms) {
  std::string line;
  char c;
  pollfd p{fd, POLLIN, 0};
  while (::poll(&p, 1, timeout_ms) > 0 && ::read(fd, &c, 1) == 1 && c != '\n') line += c;
  return line;
}

TEST(ServerCli, FlagsWithoutASubcommandServe) {
  const auto data = std::filesystem::temp_directory_path() / ("fw-cli-serve-" + std::to_string(::getpid()));
  int out = -1;
  const pid_t pid = test::spawn_shell(
      "exec " + server_command("--http 127.0.0.1:0 --no-demo-room --data " + data.string()), false, out);
  ASSERT_GT(pid, 0);
  const std::string line = first_line(out, 10000);
  ASSERT_NE(line.find("facewire-server listening on http://127.0.0.1:"), std::string::npos) << line;
  const int port = std::atoi(line.c_str() + line.rfind(':') + 1);
  EXPECT_EQ(http_get(port, "/healthz").status, 200);
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "drains and exits 0 on SIGTERM";
  ::close(out);
  std::filesystem::remove_all(data);
}

TEST(ServerCli, AnUnknownFlagIsAUsageErrorThatNamesIt) {
  // Every subcommand, given what it requires, so that the unknown flag is the only error.
  const std::string scene = test::bin("facewire-server");  // any file that exists
  for (const std::string& command : {std::string(""), std::string("serve"), std::string("token --room r --name Ann"),
                                     std::string("prep photo.jpg -o out.fwa"), std::string("script file.fws"),
                                     std::string("simulate -o out.fws"), "render-scene " + scene}) {
    const auto result = test::run_command(server_command(command + " --no-such-flag"));
    EXPECT_EQ(result.status, 2) << command << ": " << result.output;
    EXPECT_NE(result.output.find("--no-such-flag"), std::string::npos) << command << ": " << result.output;
  }
}

TEST(ServerCli, ABadValueIsAUsageErrorThatNamesTheFlag) {
  const std::string scene = test::bin("facewire-server");
  for (const auto& [command, flag] : std::vector<std::pair<std::string, std::string>>{
           {"--threads abc", "--threads"},
           {"--room-size 0", "--room-size"},
           {"serve --tick-hz 1000", "--tick-hz"},
           {"--log-level loud", "--log-level"},
           {"--no-demo-room=maybe", "--no-demo-room"},
           {"--http localhost", "--http"},
           {"--tcp 127.0.0.1:http", "--tcp"},
           {"--http", "--http"},
           {"token --room r --name Ann --ttl -5", "--ttl"},
           {"token --room r", "--name"},
           {"token --room 'a b' --name Ann --auth-secret s", "--room"},
           {"token --room r --name \u202Eevil --auth-secret s", "--name"},
           {"prep photo.jpg -o out.fwa --quality 500", "--quality"},
           {"simulate -o out.fws --avatars 0", "--avatars"},
           {"render-scene " + scene + " --every 0", "--every"}}) {
    const auto result = test::run_command(server_command(command));
    EXPECT_EQ(result.status, 2) << command << ": " << result.output;
    EXPECT_NE(result.output.find(flag), std::string::npos) << command << ": " << result.output;
  }
}

TEST(ServerCli, AMissingRequiredOptionIsAUsageError) {
  const auto result = test::run_command(server_command("token"));
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find("--room is required"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("facewire-server token --help"), std::string::npos) << "says where to look";
}

TEST(ServerCli, HelpIsNoError) {
  for (const char* command : {"--help", "serve --help", "token --help"}) {
    const auto result = test::run_command(server_command(command));
    EXPECT_EQ(result.status, 0) << command << ": " << result.output;
    EXPECT_NE(result.output.find("Options:"), std::string::npos) << command << ": " << result.output;
  }
  EXPECT_NE(test::run_command(server_command("--help")).output.find("serve"), std::string::npos)
      << "the top-level help lists the subcommands";
}

}  // namespace
}  // namespace fw::server
