#include "socket_queue.hpp"

#include <linux/sockios.h>
#include <sys/ioctl.h>

namespace fw::server {

std::optional<std::size_t> socket_unacknowledged_bytes(int fd) {
  if (fd < 0) return std::nullopt;
  int bytes = 0;
  if (::ioctl(fd, SIOCOUTQ, &bytes) != 0 || bytes < 0) return std::nullopt;
  return static_cast<std::size_t>(bytes);
}

}  // namespace fw::server
