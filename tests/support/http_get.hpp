#pragma once
// A minimal HTTP/1.1 client over a plain socket, so tests see exactly the
// bytes the server sends (and can send bytes no library would).
#include <sys/socket.h>
#include <unistd.h>

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

/// Sends `raw` on the connected socket `fd`, reads the answer until the
/// server closes, and closes `fd`.
inline HttpReply http_exchange_on(int fd, const std::string& raw) {
  HttpReply reply;
  ::send(fd, raw.data(), raw.size(), MSG_NOSIGNAL);
  std::string received;
  char buffer[8192];
  ssize_t n;
  while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0) received.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  const auto header_end = received.find("\r\n\r\n");
  if (received.rfind("HTTP/1.1 ", 0) != 0 || header_end == std::string::npos) return reply;
  reply.status = std::atoi(received.c_str() + 9);
  reply.headers = received.substr(0, header_end);
  reply.body = received.substr(header_end + 4);
  return reply;
}

/// GET `path` with Connection: close and optional extra header lines.
inline HttpReply http_get(int port, const std::string& path, const std::string& extra_headers = "") {
  return http_exchange(port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra_headers +
                                 "Connection: close\r\n\r\n");
}

}  // namespace fw::test
