#pragma once
// File descriptors running out. A listener whose accept() fails for want
// of descriptors (EMFILE, ENFILE) leaves the connection waiting in the
// kernel's queue, so the next accept fails at once too: without care the
// server spins and logs millions of lines. A DescriptorReserve holds one
// descriptor back (on /dev/null) so that the listener can give it up,
// accept a waiting connection, tell it the server is full, close it and
// take the reserve again, before it waits a moment and accepts again.
#include <cstddef>

#include <boost/system/error_code.hpp>

namespace fw::server {

class DescriptorReserve {
 public:
  DescriptorReserve();
  ~DescriptorReserve();
  DescriptorReserve(const DescriptorReserve&) = delete;
  DescriptorReserve& operator=(const DescriptorReserve&) = delete;

  /// Gives the reserved descriptor back to the process; false if none was held.
  bool release();
  /// Takes a descriptor into reserve again; false if none is free (another
  /// thread took the one released meanwhile): the next restore() tries again.
  bool restore();
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

/// accept()'s "too many open files" (the process's limit or the system's).
bool is_descriptor_exhaustion(const boost::system::error_code& ec);

/// Raises the process's soft limit on open files to its hard limit, as far
/// as `most`: the soft default (often 1024) is far below what a server that
/// holds thousands of connections needs, and the hard limit is what the
/// operator allowed. Returns the limit in force.
unsigned long raise_descriptor_limit(unsigned long most);

/// Descriptors kept for what is not a connection: files of the avatar
/// store, photos, the log, Redis, the reserves.
inline constexpr unsigned long kDescriptorsForFiles = 64;

/// Connections each of `ports` may hold with `descriptors` open files in
/// all (kDescriptorsForFiles kept aside), as far as `most`; at least 1.
std::size_t connections_per_port(unsigned long descriptors, std::size_t ports, std::size_t most);

}  // namespace fw::server
