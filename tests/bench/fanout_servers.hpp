#pragma once
// The servers a `facewire-bench fanout` run measures: one facewire-server
// with no Redis (one node, the embedded default), or a redis-server and N
// cluster nodes on it (`--redis`, `--node nK`), each node with a data
// directory of its own. Also what the run reads of them: CPU time and
// memory from /proc, which node owns a room from Redis.
#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fw::test {
class RedisProcess;
class ServerProcess;
}  // namespace fw::test

namespace fw::bench::fanout {

/// CPU seconds (user + system) of a process, from /proc/PID/stat.
double process_cpu_seconds(pid_t pid);
/// A line of /proc/PID/status in megabytes (VmRSS, VmHWM).
double process_status_mb(pid_t pid, const std::string& key);

class FanoutServers {
 public:
  /// Starts `nodes` servers (`binary serve --http 127.0.0.1:0 common_args
  /// --data DIR`, plus `--redis URL --node nK` from two nodes on) and waits
  /// until each answers /readyz with 200 (a cluster node: once it is
  /// connected to Redis). error() says what failed, if anything did.
  FanoutServers(const std::string& binary, const std::string& common_args, int nodes);
  /// Kills what it started and removes the data directories.
  ~FanoutServers();
  FanoutServers(const FanoutServers&) = delete;
  FanoutServers& operator=(const FanoutServers&) = delete;

  const std::string& error() const { return error_; }
  int nodes() const { return static_cast<int>(nodes_.size()); }
  bool clustered() const { return redis_ != nullptr; }
  /// The name given with --node ("n1", "n2", ...; "" for one process).
  const std::string& node_name(int i) const { return names_.at(static_cast<std::size_t>(i)); }
  int http_port(int i) const;
  pid_t node_pid(int i) const;
  /// Redis' CPU seconds so far; 0 with no Redis.
  double redis_cpu_seconds() const;
  /// The node whose lease on `room` Redis holds now; "" with no Redis or no owner.
  std::string owner_of(const std::string& room) const;

 private:
  std::unique_ptr<test::RedisProcess> redis_;
  std::vector<std::unique_ptr<test::ServerProcess>> nodes_;
  std::vector<std::string> names_;
  std::vector<std::filesystem::path> data_;
  std::string error_;
};

}  // namespace fw::bench::fanout
