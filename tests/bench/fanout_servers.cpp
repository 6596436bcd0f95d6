#include "fanout_servers.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "http_get.hpp"
#include "loopback_socket.hpp"
#include "redis_process.hpp"
#include "server_process.hpp"

namespace fw::bench::fanout {

double process_cpu_seconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = stat.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return 0;
  std::istringstream fields(stat.substr(close + 2));
  std::string field;
  double utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stod(field);
    if (i == 15) stime = std::stod(field);
  }
  return (utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

double process_status_mb(pid_t pid, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;
  return 0;
}

namespace {

// GET `key` over a plain socket: "" for a missing key or no answer. The
// bench asks Redis a handful of questions after its window, so a blocking
// exchange of RESP is all it needs.
std::string redis_get(int port, const std::string& key) {
  const int fd = test::connect_loopback(port, 2);
  if (fd < 0) return {};
  const std::string request = "*2\r\n$3\r\nGET\r\n$" + std::to_string(key.size()) + "\r\n" + key + "\r\n";
  ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
  std::string reply;
  char buffer[512];
  // A bulk string: "$LEN\r\nVALUE\r\n", or "$-1\r\n" for none.
  while (true) {
    const auto header_end = reply.find("\r\n");
    if (header_end != std::string::npos) {
      if (reply[0] != '$' || reply.compare(0, 3, "$-1") == 0) break;
      const auto length = static_cast<std::size_t>(std::stoul(reply.substr(1, header_end - 1)));
      if (reply.size() >= header_end + 2 + length) {
        reply = reply.substr(header_end + 2, length);
        ::close(fd);
        return reply;
      }
    }
    const auto n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return {};
}

}  // namespace

FanoutServers::FanoutServers(const std::string& binary, const std::string& common_args, int nodes) {
  std::string cluster_args;
  if (nodes >= 2) {
    redis_ = std::make_unique<test::RedisProcess>();
    if (!redis_->ok()) {
      error_ = redis_->error();
      return;
    }
    cluster_args = " --redis " + redis_->url();
  }
  const auto temp = std::filesystem::temp_directory_path();
  for (int i = 0; i < nodes; ++i) {
    const std::string name = nodes >= 2 ? "n" + std::to_string(i + 1) : "";
    const auto data = temp / ("facewire-bench-fanout-" + std::to_string(::getpid()) + (name.empty() ? "" : "-" + name));
    data_.push_back(data);
    names_.push_back(name);
    const std::string args =
        common_args + " --data " + data.string() + cluster_args + (name.empty() ? "" : " --node " + name);
    nodes_.push_back(std::make_unique<test::ServerProcess>(binary, args));
    if (nodes_.back()->port() == 0) {
      error_ = "facewire-server did not start (" + binary + " serve " + args + ")";
      return;
    }
  }
  // A cluster node is ready once it is connected to Redis; clients that
  // came earlier would be refused or served as by a lone process.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  for (int i = 0; i < nodes; ++i) {
    while (test::http_get(http_port(i), "/readyz").status != 200) {
      if (std::chrono::steady_clock::now() > deadline) {
        error_ = "node " + std::to_string(i + 1) + " did not answer /readyz with 200 within 30 s" +
                 (clustered() ? " (is it connected to " + redis_->url() + "?)" : "");
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
}

FanoutServers::~FanoutServers() {
  nodes_.clear();  // the nodes first: they would otherwise see Redis go
  redis_.reset();
  for (const auto& data : data_) {
    std::error_code ignored;
    std::filesystem::remove_all(data, ignored);
  }
}

int FanoutServers::http_port(int i) const { return nodes_.at(static_cast<std::size_t>(i))->port(); }
pid_t FanoutServers::node_pid(int i) const { return nodes_.at(static_cast<std::size_t>(i))->pid(); }
double FanoutServers::redis_cpu_seconds() const { return redis_ ? redis_->cpu_seconds() : 0.0; }

std::string FanoutServers::owner_of(const std::string& room) const {
  // The key's name is the cluster's (server/cluster/cluster_keys.hpp, room_owner).
  return redis_ ? redis_get(redis_->port(), "fw:room:" + room + ":owner") : std::string();
}

}  // namespace fw::bench::fanout
