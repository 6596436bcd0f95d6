#include "descriptor_reserve.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace fw::server {

DescriptorReserve::DescriptorReserve() { restore(); }

DescriptorReserve::~DescriptorReserve() { release(); }

bool DescriptorReserve::release() {
  if (fd_ < 0) return false;
  ::close(fd_);
  fd_ = -1;
  return true;
}

bool DescriptorReserve::restore() {
  if (fd_ < 0) fd_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  return fd_ >= 0;
}

bool is_descriptor_exhaustion(const boost::system::error_code& ec) {
  if (ec.category() != boost::system::system_category() && ec.category() != boost::system::generic_category())
    return false;
  return ec.value() == EMFILE || ec.value() == ENFILE;
}

unsigned long raise_descriptor_limit(unsigned long most) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return 0;
  const rlim_t wanted = std::min<rlim_t>(limit.rlim_max, most);
  if (limit.rlim_cur < wanted) {
    rlimit raised = limit;
    raised.rlim_cur = wanted;
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
  }
  return static_cast<unsigned long>(limit.rlim_cur);
}

std::size_t connections_per_port(unsigned long descriptors, std::size_t ports, std::size_t most) {
  if (descriptors == 0) return most;  // the limit is unknown
  const unsigned long for_connections = descriptors > kDescriptorsForFiles ? descriptors - kDescriptorsForFiles : 1;
  const std::size_t each = static_cast<std::size_t>(for_connections) / std::max<std::size_t>(ports, 1);
  return std::clamp<std::size_t>(each, 1, most);
}

}  // namespace fw::server
