// POST /api/avatars as the browser lobby uses it (server/PROTOCOL.md,
// section 8): a multipart form with a photo alone, the advice in the
// answer, a rate limit that says when to try again, and refusals a browser
// can read even while it is still sending the body. The real server on
// real sockets.
#include <sys/socket.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "http_get.hpp"
#include "loopback_socket.hpp"
#include "photo_variants.hpp"
#include "room_test_server.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using test::RunningServer;

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

/// A browser's FormData with one file part named `photo`.
std::string photo_form(const std::string& boundary, const std::string& type, const std::string& photo) {
  std::string part = "--" + boundary + "\r\nContent-Disposition: form-data; name=\"photo\"; filename=\"me.jpg\"\r\n";
  if (!type.empty()) part += "Content-Type: " + type + "\r\n";
  return part + "\r\n" + photo + "\r\n--" + boundary + "--\r\n";
}

/// test::http_exchange with time for a photo's preparation: the first
/// loads the landmark model, which takes seconds on a busy machine.
test::HttpReply exchange_slowly(int port, const std::string& raw) { return test::http_exchange(port, raw, 60); }

test::HttpReply post_form(int port, const std::string& body, const std::string& boundary = "----WebKitFormBoundaryX") {
  return exchange_slowly(port, "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                   "Content-Type: multipart/form-data; boundary=" + boundary +
                                   "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
}

std::string encode_jpeg(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  cv::imencode(".jpg", image, bytes);
  return {bytes.begin(), bytes.end()};
}

TEST(BrowserUpload, APhotoAloneInAFormIsPreparedAndItsAdviceComesBack) {
  RunningServer server("--no-demo-room");
  // Stored sideways: the pipeline turns it and says so, which is advice.
  cv::Mat sideways;
  cv::rotate(cv::imread(test::test_photo("grace_hopper.jpg")), sideways, cv::ROTATE_90_CLOCKWISE);
  const std::string photo = encode_jpeg(sideways);
  const auto reply = post_form(server.http_port(), photo_form("----WebKitFormBoundaryX", "image/jpeg", photo));
  ASSERT_EQ(reply.status, 201) << reply.body;
  const auto answer = nlohmann::json::parse(reply.body);
  const std::string asset = answer["asset"];
  EXPECT_EQ(answer["package"], "/api/packages/" + asset);
  ASSERT_TRUE(answer["advice"].is_array()) << reply.body;
  ASSERT_FALSE(answer["advice"].empty()) << reply.body;
  EXPECT_NE(answer["advice"][0].get<std::string>().find("turned"), std::string::npos) << reply.body;
  const auto package = test::http_get(server.http_port(), answer["package"]);
  ASSERT_EQ(package.status, 200);
  EXPECT_EQ(package.body.size(), answer["bytes"].get<std::size_t>());
  EXPECT_EQ(read_bytes(server.data() / "avatars" / (asset + ".photo")), photo) << "the photo is kept as sent";

  // A package upload has no advice, but the field is there.
  const auto again = exchange_slowly(server.http_port(),
      "POST /api/avatars HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Type: application/x-facewire-avatar\r\n"
      "Content-Length: " + std::to_string(package.body.size()) + "\r\n\r\n" + package.body);
  ASSERT_EQ(again.status, 201) << again.body;
  EXPECT_EQ(nlohmann::json::parse(again.body)["advice"], nlohmann::json::array());
}

TEST(BrowserUpload, AFormPhotoThatCannotServeIsRefusedWithAReason) {
  RunningServer server("--no-demo-room");
  const int port = server.http_port();
  // No face: a flat grey picture.
  const std::string wall = encode_jpeg(cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128)));
  const auto no_face = post_form(port, photo_form("b", "image/jpeg", wall), "b");
  EXPECT_EQ(no_face.status, 422) << no_face.body;
  EXPECT_NE(no_face.body.find("face"), std::string::npos) << no_face.body;
  // A browser names the type from the file name, or not at all: the bytes decide.
  const auto untyped = post_form(port, photo_form("b", "", "not a photo at all"), "b");
  EXPECT_EQ(untyped.status, 422) << untyped.body;
  EXPECT_NE(untyped.body.find("not an image"), std::string::npos) << untyped.body;
  const auto gif = post_form(port, photo_form("b", "image/gif", "GIF89a"), "b");
  EXPECT_EQ(gif.status, 415) << gif.body;
  EXPECT_NE(gif.body.find("JPEG, PNG or WebP"), std::string::npos) << gif.body;
  const auto nothing = post_form(port, "--b\r\nContent-Disposition: form-data; name=\"other\"\r\n\r\nx\r\n--b--\r\n", "b");
  EXPECT_EQ(nothing.status, 400) << nothing.body;
  EXPECT_NE(nothing.body.find("'photo'"), std::string::npos) << nothing.body;
  EXPECT_NE(no_face.headers.find("Content-Type: text/plain"), std::string::npos) << "errors stay plain text";
}

TEST(BrowserUpload, TheRateLimitSaysWhenToTryAgain) {
  RunningServer server("--no-demo-room");
  for (int i = 0; i < 6; ++i) EXPECT_EQ(post_form(server.http_port(), photo_form("b", "", "x"), "b").status, 422) << i;
  const auto refused = post_form(server.http_port(), photo_form("b", "", "x"), "b");
  ASSERT_EQ(refused.status, 429) << refused.body;
  std::smatch header, body;
  ASSERT_TRUE(std::regex_search(refused.headers, header, std::regex("Retry-After: (\\d+)"))) << refused.headers;
  const int wait = std::stoi(header[1]);
  // Six a minute, six at once: the next comes ten seconds after the first.
  EXPECT_GE(wait, 1);
  EXPECT_LE(wait, 10);
  ASSERT_TRUE(std::regex_search(refused.body, body, std::regex("try again in (\\d+) seconds"))) << refused.body;
  EXPECT_EQ(std::stoi(body[1]), wait) << "the body and the header agree";
}

// A browser sends the whole body before it reads the answer; a server that
// refuses a large upload from its header and closes at once resets the
// connection under it, and the browser shows the reset instead of the 413.
TEST(BrowserUpload, ATooLargeUploadIsAnsweredWhileTheBodyIsStillComing) {
  RunningServer server("--no-demo-room --max-upload-bytes 65536");
  const int fd = test::connect_loopback(server.http_port(), 10);
  ASSERT_GE(fd, 0);
  const std::string body(2 * 1024 * 1024, 'x');
  const std::string head = "POST /api/avatars HTTP/1.1\r\nHost: x\r\nContent-Type: image/jpeg\r\nContent-Length: " +
                           std::to_string(body.size()) + "\r\n\r\n";
  ASSERT_EQ(::send(fd, head.data(), head.size(), MSG_NOSIGNAL), static_cast<ssize_t>(head.size()));
  std::size_t sent = 0;
  while (sent < body.size()) {
    const ssize_t n = ::send(fd, body.data() + sent, std::min<std::size_t>(65536, body.size() - sent), MSG_NOSIGNAL);
    ASSERT_GT(n, 0) << "the server reset the connection after " << sent << " bytes of the body";
    sent += static_cast<std::size_t>(n);
  }
  std::string received;
  char buffer[4096];
  ssize_t n;
  while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0) received.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  EXPECT_EQ(received.rfind("HTTP/1.1 413", 0), 0u) << received;
  EXPECT_NE(received.find("at most 64 KiB"), std::string::npos) << received;
}

TEST(BrowserUpload, EveryFileOfTheWebFolderIsServedWithItsType) {
  RunningServer server("--no-demo-room");
  const std::filesystem::path web = test::source_path("web");
  const std::map<std::string, std::string> types = {
      {".html", "text/html"}, {".js", "text/javascript"}, {".mjs", "text/javascript"},
      {".css", "text/css"},   {".json", "application/json"}, {".wasm", "application/wasm"}};
  int served = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(web)) {
    const auto type = types.find(entry.path().extension().string());
    if (!entry.is_regular_file() || type == types.end()) continue;
    const std::string path = "/" + std::filesystem::relative(entry.path(), web).generic_string();
    const auto reply = test::http_get(server.http_port(), path);
    ASSERT_EQ(reply.status, 200) << path << ": rebuild after adding a file to web/ (" << reply.body << ")";
    EXPECT_NE(reply.headers.find("Content-Type: " + type->second), std::string::npos) << path << reply.headers;
    EXPECT_EQ(reply.body, read_bytes(entry.path())) << path;
    ++served;
  }
  EXPECT_GE(served, 10);
  EXPECT_EQ(test::http_get(server.http_port(), "/").body, read_bytes(web / "index.html"));
  EXPECT_EQ(test::http_get(server.http_port(), "/README.md").status, 404) << "only what the browser loads";
  EXPECT_EQ(test::http_get(server.http_port(), "/shaders/face.frag").status, 200);
  EXPECT_EQ(test::http_get(server.http_port(), "/generic_face.json").status, 200);
}

TEST(InviteLink, TheTokenCommandPrintsTheTokenThenTheLink) {
  const auto minted = test::run_command(test::bin("facewire-server") +
                                            " token --room team.a --name 'Ann Lee' --ttl 60 --auth-secret s3cret"
                                            " --url https://faces.example.org:8443",
                                        /*with_stderr=*/false);
  ASSERT_EQ(minted.status, 0) << minted.output;
  const std::string token = minted.output.substr(0, minted.output.find('\n'));
  EXPECT_EQ(token.rfind("fw1.", 0), 0u) << minted.output;
  const std::string link = minted.output.substr(token.size() + 1, minted.output.find('\n', token.size() + 1) - token.size() - 1);
  EXPECT_EQ(link, "https://faces.example.org:8443/?room=team.a&name=Ann%20Lee&token=" + token);

  const auto default_url = test::run_command(test::bin("facewire-server") + " token --room r --name Bo --auth-secret s", false);
  ASSERT_EQ(default_url.status, 0) << default_url.output;
  EXPECT_NE(default_url.output.find("\nhttp://127.0.0.1:8080/?room=r&name=Bo&token=fw1."), std::string::npos)
      << default_url.output;

  const auto bad = test::run_command(test::bin("facewire-server") + " token --room r --name Bo --auth-secret s --url ftp://x");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("http://HOST:PORT/"), std::string::npos) << bad.output;
}

TEST(InviteLink, ItsTokenOpensTheRoom) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const auto minted = test::run_command(
      test::bin("facewire-server") + " token --room a --name Ann --auth-secret s3cret --url http://127.0.0.1:" +
          std::to_string(server.http_port()) + "/", false);
  ASSERT_EQ(minted.status, 0);
  const std::regex query("\\?room=a&name=Ann&token=(fw1\\.[A-Za-z0-9_.-]+)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(minted.output, match, query)) << minted.output;
  auto joined = test::join(server, test::Transport::websocket, "a", "Ann", match[1]);
  EXPECT_TRUE(joined->welcome) << (joined->closing ? joined->closing->reason : "no answer");
}

}  // namespace
}  // namespace fw::server
