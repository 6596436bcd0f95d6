#pragma once
// What a running server is doing, as flags that change while it runs: the
// parts that change them (ServerCore, a cluster node) and those that read
// them (/readyz, sessions, rooms) hold this one object, which ServerCore
// owns. Thread-safe: atomics, written and read from any thread.
#include <atomic>

namespace fw::server {

struct ServerState {
  std::atomic<bool> ready{false};      ///< /readyz: listening and the demo room seated
  std::atomic<bool> draining{false};   ///< SIGTERM: no new joins, sessions told to leave
  std::atomic<bool> cluster_up{true};  ///< /readyz: a cluster node reaches Redis (always, in one process)
};

}  // namespace fw::server
