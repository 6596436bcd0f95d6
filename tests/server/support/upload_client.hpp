#pragma once
// Uploads as the limits' tests make them (upload_limits_test.cpp,
// upload_starvation_test.cpp): raw sockets from a chosen loopback address
// (127.x.y.z: another client, in another /24 when y differs), exact headers,
// bodies sent whole or in part, and the answer read as it comes.
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "http_get.hpp"
#include "loopback_socket.hpp"
#include "room_test_server.hpp"

namespace fw::test {

using namespace std::chrono_literals;

inline constexpr std::size_t kMiB = 1024 * 1024;

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

/// A socket to the server's port from `source` (127.x.y.z: another client),
/// whose sends give up after 20 s.
inline int connect_from(const std::string& source, int port) {
  const int fd = connect_loopback_from(source.c_str(), port, 60);
  if (fd < 0) return -1;
  timeval send_timeout{20, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof send_timeout);
  return fd;
}

inline bool send_all(int fd, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

inline std::string upload_header(const std::string& type, std::size_t length) {
  return "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: " + type +
         "\r\nContent-Length: " + std::to_string(length) + "\r\n\r\n";
}

/// The answer the server sends within `wait` (it closes after a refusal),
/// or nullopt when none comes: the server is waiting for the body.
inline std::optional<HttpReply> answer_within(int fd, std::chrono::milliseconds wait) {
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
  HttpReply reply;
  reply.status = std::atoi(received.c_str() + 9);
  reply.headers = received.substr(0, end);
  reply.body = received.substr(end + 4);
  return reply;
}

/// The Retry-After header's seconds; -1 when there is none.
inline int retry_after(const HttpReply& reply) {
  std::smatch match;
  if (!std::regex_search(reply.headers, match, std::regex("Retry-After: (\\d+)"))) return -1;
  return std::stoi(match[1]);
}

/// A whole upload from `source`, its answer read (a photo's preparation may
/// load the landmark model first: a minute's patience).
inline HttpReply upload_from(const std::string& source, int port, const std::string& type, const std::string& body) {
  const int fd = connect_from(source, port);
  if (fd < 0) return {};
  send_all(fd, upload_header(type, body.size()) + body);
  auto reply = answer_within(fd, 60s);
  ::close(fd);
  return reply.value_or(HttpReply{});
}

inline long refusals(const RunningServer& server, const std::string& kind) {
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

}  // namespace fw::test
