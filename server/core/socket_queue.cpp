#include "socket_queue.hpp"

#include <linux/sockios.h>
#include <linux/tcp.h>
#include <netinet/in.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#include <cstddef>

namespace fw::server {

std::optional<SocketQueue> socket_queue(int fd) {
  if (fd < 0) return std::nullopt;
  int bytes = 0;
  if (::ioctl(fd, SIOCOUTQ, &bytes) != 0 || bytes < 0) return std::nullopt;
  SocketQueue queue;
  queue.unacknowledged = static_cast<std::size_t>(bytes);
  tcp_info info{};
  socklen_t length = sizeof info;
  if (::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &length) == 0 &&
      length >= offsetof(tcp_info, tcpi_snd_wnd) + sizeof info.tcpi_snd_wnd)
    queue.peer_window = info.tcpi_snd_wnd;
  return queue;
}

}  // namespace fw::server
