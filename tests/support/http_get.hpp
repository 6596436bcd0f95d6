#pragma once
// A minimal HTTP/1.1 client over a plain socket, so tests see exactly the
// bytes the server sends (and can send bytes no library would); from
// 127.0.0.1, or from a chosen loopback address for the tests of what is
// counted per address and per network block.
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>

#include "loopback_socket.hpp"

namespace fw::test {

struct HttpReply {
  int status = 0;  ///< 0 if the connection failed or closed without a status line
  std::string headers;
  std::string body;
};

/// Sends `raw` to 127.0.0.1:`port` and reads until the server closes or
/// `timeout_s` seconds pass.
inline HttpReply http_exchange_on(int fd, const std::string& raw);
inline HttpReply http_exchange(int port, const std::string& raw, int timeout_s = 5) {
  const int fd = connect_loopback(port, timeout_s);
  if (fd < 0) return {};
  return http_exchange_on(fd, raw);
}

/// The status, headers and body of an answer as received; status 0 when it
/// has no whole status line and header.
inline HttpReply parse_http_reply(const std::string& received) {
  HttpReply reply;
  const auto header_end = received.find("\r\n\r\n");
  if (received.rfind("HTTP/1.1 ", 0) != 0 || header_end == std::string::npos) return reply;
  reply.status = std::atoi(received.c_str() + 9);
  reply.headers = received.substr(0, header_end);
  reply.body = received.substr(header_end + 4);
  return reply;
}

/// Sends `raw` on the connected socket `fd`, reads the answer until the
/// server closes, and closes `fd`.
inline HttpReply http_exchange_on(int fd, const std::string& raw) {
  ::send(fd, raw.data(), raw.size(), MSG_NOSIGNAL);
  std::string received;
  char buffer[8192];
  ssize_t n;
  while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0) received.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  return parse_http_reply(received);
}

/// Sends `raw` from the loopback address `source` (127.x.y.z: a client the
/// server counts apart, e.g. "127.0.7.1") and reads until the server closes
/// or `timeout` passes; status 0 when no whole answer came by then (the
/// server holds the request, or refused the connection).
inline HttpReply http_from(const std::string& source, int port, const std::string& raw,
                           std::chrono::milliseconds timeout = std::chrono::seconds(5)) {
  const int fd = connect_loopback_from(source.c_str(), port, 0);
  if (fd < 0) return {};
  // Bodies of uploads are larger than one send: a blocking send, bounded
  // by the same time-out in case the server stops reading.
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(timeout).count();
  timeval send_timeout{static_cast<time_t>(std::max<long long>(seconds, 1)), 0};
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof send_timeout);
  for (std::size_t sent = 0; sent < raw.size();) {
    const ssize_t n = ::send(fd, raw.data() + sent, raw.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;  // refused mid-request: what it answered is still read
    sent += static_cast<std::size_t>(n);
  }
  std::string received;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  Received part;
  do {
    part = receive_for(fd, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
    received += part.bytes;
  } while (!part.closed && std::chrono::steady_clock::now() < deadline);
  ::close(fd);
  return parse_http_reply(received);
}

/// GET `path` from the loopback address `source`, with Connection: close.
inline HttpReply get_from(const std::string& source, int port, const std::string& path,
                          std::chrono::milliseconds timeout = std::chrono::seconds(5)) {
  return http_from(source, port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n",
                   timeout);
}

/// facewire_refusals_total{kind="`kind`"} in the server's /metrics, asked
/// from `source` (a test that fills an address's share asks from another);
/// -1 when the kind is not listed or /metrics did not answer.
inline long refusal_count(int http_port, const std::string& kind, const std::string& source = "127.0.0.1") {
  const auto metrics = get_from(source, http_port, "/metrics");
  const std::string key = "facewire_refusals_total{kind=\"" + kind + "\"} ";
  const auto at = metrics.body.find(key);
  if (metrics.status != 200 || at == std::string::npos) return -1;
  return std::atol(metrics.body.c_str() + at + key.size());
}

/// GET `path` with Connection: close and optional extra header lines.
inline HttpReply http_get(int port, const std::string& path, const std::string& extra_headers = "") {
  return http_exchange(port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra_headers +
                                 "Connection: close\r\n\r\n");
}

}  // namespace fw::test
