// Uploads against the limits that keep one client from taking the server's
// memory or its photo preparation (server/PROTOCOL.md, "Limits"): an upload
// is refused from its header, before its body is read, when its address is
// over its rate or holds its share of bytes in flight, when the server's
// bytes in flight are taken, or when the photo queue is full; each refusal
// says when to try again (Retry-After), and other addresses still upload.
// The real server on loopback sockets; other clients connect from
// 127.0.0.2 and up.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "http_get.hpp"
#include "room_test_server.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::RunningServer;

constexpr std::size_t kMiB = 1024 * 1024;

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

/// A socket to the server's port from `source` (127.0.0.x: another client).
int connect_from(const std::string& source, int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_in local{};
  local.sin_family = AF_INET;
  ::inet_pton(AF_INET, source.c_str(), &local.sin_addr);
  sockaddr_in remote{};
  remote.sin_family = AF_INET;
  remote.sin_port = htons(static_cast<std::uint16_t>(port));
  remote.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  timeval send_timeout{20, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof send_timeout);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0 ||
      ::connect(fd, reinterpret_cast<sockaddr*>(&remote), sizeof remote) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

bool send_all(int fd, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

std::string upload_header(const std::string& type, std::size_t length) {
  return "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: " + type +
         "\r\nContent-Length: " + std::to_string(length) + "\r\n\r\n";
}

/// The answer the server sends within `wait` (it closes after a refusal),
/// or nullopt when none comes: the server is waiting for the body.
std::optional<test::HttpReply> answer_within(int fd, std::chrono::milliseconds wait) {
  std::string received;
  const auto until = std::chrono::steady_clock::now() + wait;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    pollfd p{fd, POLLIN, 0};
    if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    char buffer[4096];
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    received.append(buffer, static_cast<std::size_t>(n));
  }
  const auto end = received.find("\r\n\r\n");
  if (received.rfind("HTTP/1.1 ", 0) != 0 || end == std::string::npos) return std::nullopt;
  test::HttpReply reply;
  reply.status = std::atoi(received.c_str() + 9);
  reply.headers = received.substr(0, end);
  reply.body = received.substr(end + 4);
  return reply;
}

/// The Retry-After header's seconds; -1 when there is none.
int retry_after(const test::HttpReply& reply) {
  std::smatch match;
  if (!std::regex_search(reply.headers, match, std::regex("Retry-After: (\\d+)"))) return -1;
  return std::stoi(match[1]);
}

/// A whole upload from `source`, its answer read (a photo's preparation may
/// load the landmark model first: a minute's patience).
test::HttpReply upload_from(const std::string& source, int port, const std::string& type, const std::string& body) {
  const int fd = connect_from(source, port);
  if (fd < 0) return {};
  send_all(fd, upload_header(type, body.size()) + body);
  auto reply = answer_within(fd, 60s);
  ::close(fd);
  return reply.value_or(test::HttpReply{});
}

long refusals(const RunningServer& server, const std::string& kind) {
  const auto metrics = test::http_get(server.http_port(), "/metrics");
  std::smatch match;
  if (!std::regex_search(metrics.body, match, std::regex("facewire_refusals_total\\{kind=\"" + kind + "\"\\} (\\d+)")))
    return -1;
  return std::stol(match[1]);
}

/// Open sockets, closed at the end.
struct Sockets {
  std::vector<int> fds;
  ~Sockets() {
    for (const int fd : fds) ::close(fd);
  }
};

// One address starts many 4 MiB uploads and sends most of each body, as if
// it would finish them: only its share is admitted and held; the rest are
// refused from their header at once, and the server's memory stays near
// that share. Another address still uploads its photo meanwhile.
TEST(UploadLimits, UploadsHeldOpenHoldNoMoreThanTheAddressesShare) {
  RunningServer server("--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  std::this_thread::sleep_for(500ms);
  const long rss_before = server.rss_kb();
  constexpr int kUploads = 16;
  const std::string most_of_a_body(3 * kMiB, '\xff');
  Sockets held;
  int admitted = 0, refused = 0;
  for (int i = 0; i < kUploads; ++i) {
    const int fd = connect_from("127.0.0.1", server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 4 * kMiB)));
    // The header alone decides: a refusal comes before any of the body.
    if (const auto reply = answer_within(fd, 1500ms)) {
      ++refused;
      EXPECT_TRUE(reply->status == 429 || reply->status == 503) << reply->status << " " << reply->body;
      EXPECT_GE(retry_after(*reply), 1) << reply->headers;
      EXPECT_NE(reply->body.find("try again in"), std::string::npos) << reply->body;
      continue;
    }
    ++admitted;
    ASSERT_TRUE(send_all(fd, most_of_a_body)) << "upload " << i;
  }
  std::this_thread::sleep_for(500ms);
  const long grown_mib = (server.rss_kb() - rss_before) / 1024;
  // The address's share is 8 MiB: two uploads of 4 MiB.
  EXPECT_LE(admitted, 2);
  EXPECT_EQ(refused, kUploads - admitted);
  EXPECT_LT(grown_mib, 20) << "held " << kUploads << " uploads of which " << admitted << " admitted";
  EXPECT_GE(refusals(server, "upload_bytes"), 1);

  // Another client, from another address, is not held up.
  const std::string photo = read_bytes(test::test_photo("grace_hopper.jpg"));
  const auto other = upload_from("127.0.0.2", server.http_port(), "image/jpeg", photo);
  EXPECT_EQ(other.status, 201) << other.body;
}

// Many addresses together hold no more than the server's share (64 MiB).
TEST(UploadLimits, ManyAddressesTogetherHoldNoMoreThanTheServersShare) {
  RunningServer server("--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  Sockets held;
  for (int i = 0; i < 20; ++i) {
    const int fd = connect_from("127.0.1." + std::to_string(10 + i), server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 4 * kMiB)));
  }
  // Every header is decided in a moment; the admitted wait for their bodies.
  std::this_thread::sleep_for(1500ms);
  int admitted = 0, unavailable = 0;
  for (const int fd : held.fds) {
    if (const auto reply = answer_within(fd, 100ms)) {
      EXPECT_EQ(reply->status, 503) << reply->body;
      EXPECT_GE(retry_after(*reply), 1) << reply->headers;
      ++unavailable;
    } else {
      ++admitted;
    }
  }
  EXPECT_EQ(admitted, 16);
  EXPECT_EQ(unavailable, 4);
}

// The rate is counted from the header: the seventh upload within a minute
// is refused before its body is sent, however large the body would be.
TEST(UploadLimits, TheSeventhUploadWithinAMinuteIsRefusedBeforeItsBody) {
  RunningServer server("--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  Sockets held;
  for (int i = 0; i < 6; ++i) {
    const int fd = connect_from("127.0.0.3", server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 1000)));
    EXPECT_FALSE(answer_within(fd, 300ms)) << "upload " << i << " is admitted and its body awaited";
  }
  const int fd = connect_from("127.0.0.3", server.http_port());
  ASSERT_GE(fd, 0);
  held.fds.push_back(fd);
  ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 1000)));
  const auto refused = answer_within(fd, 5s);
  ASSERT_TRUE(refused) << "no answer before the body";
  EXPECT_EQ(refused->status, 429) << refused->body;
  const int wait = retry_after(*refused);
  // Six a minute, six at once: the next in ten seconds.
  EXPECT_GE(wait, 1);
  EXPECT_LE(wait, 10);
  std::smatch said;
  ASSERT_TRUE(std::regex_search(refused->body, said, std::regex("try again in (\\d+) seconds?"))) << refused->body;
  EXPECT_EQ(std::stoi(said[1]), wait) << "the body and the header agree";
  EXPECT_EQ(refusals(server, "upload_rate"), 1);
  // Another address has its own rate.
  const int other = connect_from("127.0.0.4", server.http_port());
  held.fds.push_back(other);
  ASSERT_TRUE(send_all(other, upload_header("image/jpeg", 1000)));
  EXPECT_FALSE(answer_within(other, 300ms));
}

/// A photo that is slow to prepare: a large flat picture (nine megapixels)
/// in few bytes, which the preparer decodes and searches for a face.
std::string slow_photo() {
  std::vector<std::uint8_t> png;
  cv::imencode(".png", cv::Mat(3000, 3000, CV_8UC3, cv::Scalar(120, 130, 140)), png);
  return {png.begin(), png.end()};
}

// Slow photos from several addresses at once, with room for one waiting
// photo: those beyond it are answered 503 with Retry-After rather than
// queued without bound, and the server takes photos again once it has room.
TEST(UploadLimits, AFullPhotoQueueIsAnsweredAndTheServerRecovers) {
  RunningServer server("--no-demo-room --photo-queue 1 --photo-threads 1");
  ASSERT_GT(server.http_port(), 0);
  const std::string slow = slow_photo();
  std::vector<std::future<test::HttpReply>> replies;
  for (int i = 0; i < 6; ++i)
    replies.push_back(std::async(std::launch::async, [&, i] {
      return upload_from("127.0.2." + std::to_string(10 + i), server.http_port(), "image/png", slow);
    }));
  int unavailable = 0, prepared = 0;
  for (auto& reply : replies) {
    const auto answer = reply.get();
    if (answer.status == 503) {
      ++unavailable;
      EXPECT_GE(retry_after(answer), 1) << answer.headers;
      EXPECT_NE(answer.body.find("photos waiting"), std::string::npos) << answer.body;
    } else {
      ++prepared;
      EXPECT_EQ(answer.status, 422) << "no face in a flat picture: " << answer.body;
    }
  }
  EXPECT_GE(unavailable, 1);
  EXPECT_GE(prepared, 1);
  EXPECT_EQ(refusals(server, "photo_queue_full"), unavailable);

  const std::string photo = read_bytes(test::test_photo("grace_hopper.jpg"));
  const auto later = upload_from("127.0.2.30", server.http_port(), "image/jpeg", photo);
  EXPECT_EQ(later.status, 201) << later.body;
}

}  // namespace
}  // namespace fw::server
