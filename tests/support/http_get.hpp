#pragma once
// A minimal HTTP/1.1 client over a plain socket, so tests see exactly the
// bytes the server sends (and can send bytes no library would).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>

namespace fw::test {

struct HttpReply {
  int status = 0;  ///< 0 if the connection failed or closed without a status line
  std::string headers;
  std::string body;
};

/// Sends `raw` to 127.0.0.1:`port` and reads until the server closes or
/// 5 seconds pass.
inline HttpReply http_exchange(int port, const std::string& raw) {
  HttpReply reply;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  timeval timeout{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return reply;
  }
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
