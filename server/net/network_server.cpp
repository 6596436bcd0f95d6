#include "network_server.hpp"

#include <unistd.h>

#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <spdlog/spdlog.h>

#include "avatar_repreparation.hpp"
#include "avatar_retention.hpp"
#include "cluster_node.hpp"
#include "connection_refusal.hpp"
#include "descriptor_reserve.hpp"
#include "drain_on_signal.hpp"
#include "endpoint.hpp"
#include "http_session.hpp"
#include "listener.hpp"
#include "photo_preparation.hpp"
#include "photo_worker.hpp"
#include "rest_api.hpp"
#include "server_core.hpp"
#include "server_limits.hpp"
#include "tcp_session.hpp"

namespace fw::server {
namespace {

namespace net = boost::asio;

/// Two ports of limits::kMaxConnections each, and files besides.
constexpr unsigned long kDescriptorsWanted = 2 * limits::kMaxConnections + 1024;

/// Each port's places (ConnectionShares): --max-connections, or fewer when
/// the open-files limit allows fewer, so that a port fills (and a newcomer
/// takes the place of a connection that waits) before descriptors run out.
ConnectionShareLimits port_shares(const ServerConfig& config, unsigned long descriptors) {
  ConnectionShareLimits shares;
  const std::size_t ports = config.tcp.empty() ? 1 : 2;
  shares.max_total = connections_per_port(descriptors, ports, config.max_connections);
  shares.per_block = config.abuse.connections_per_block;
  shares.fresh_reserve = shares.max_total * config.abuse.fresh_share_percent / 100;
  return shares;
}

int cannot_start(const std::string& why) {
  std::cerr << "facewire-server: " << why << "\n";
  return 2;
}

/// A listener on `address` (the value of `flag`), accepting; null and `error` if it cannot listen.
/// `proxies`: whose connections its sessions count by the client they forward (Listener).
std::shared_ptr<Listener> listen(net::io_context& ioc, const HttpServices& services, const std::string& flag,
                                 const std::string& address, Listener::SessionFactory factory,
                                 Listener::Refusal refusal, ConnectionShareLimits shares, std::string& error,
                                 const TrustedProxies* proxies = nullptr) {
  const auto endpoint = parse_endpoint(address, error);
  if (!endpoint) {
    error = flag + " " + error;
    return nullptr;
  }
  boost::beast::error_code ec;
  auto listener =
      std::make_shared<Listener>(services.abuse, services.addresses, ioc, *endpoint, std::move(factory),
                                 std::move(refusal), shares, ec, proxies);
  if (ec) {
    error = "cannot listen on " + address + ": " + ec.message() +
            " (is another server using the port? choose another with " + flag + " ADDR:PORT)";
    return nullptr;
  }
  listener->run();
  return listener;
}

struct Listeners {
  std::shared_ptr<Listener> http;
  std::shared_ptr<Listener> tcp;  ///< null without --tcp

  /// A drain stops the room port only: the HTTP port keeps answering, so
  /// that /readyz says 503 "draining" to the balancer that asks (a closed
  /// port reads as a dead node, not a leaving one), and a WebSocket hello
  /// is told "shutting down" instead of meeting a reset. It closes when the
  /// loop stops.
  void stop_room_port() {
    if (tcp) tcp->stop();
  }
};

/// `services`: what each HTTP session is made with; a TCP session is made
/// with its `sessions`.
bool open_listeners(net::io_context& ioc, const HttpServices& services, Listeners& listeners,
                    unsigned long descriptors, std::string& error) {
  const ServerConfig& config = services.config;
  const ConnectionShareLimits shares = port_shares(config, descriptors);
  if (shares.max_total < config.max_connections)
    spdlog::info("open files limited to {}: {} connections at most on each port (ulimit -n)", descriptors,
                 shares.max_total);
  // Each session keeps its connection's ticket until the connection closes.
  const auto http_session = [&services](net::ip::tcp::socket&& socket, ConnectionTicket&& ticket) {
    std::make_shared<HttpSession>(services, std::move(socket), std::move(ticket))->run();
  };
  const auto tcp_session = [&sessions = services.sessions](net::ip::tcp::socket&& socket, ConnectionTicket&& ticket) {
    boost::system::error_code ec;
    std::string peer = socket.remote_endpoint(ec).address().to_string();
    std::make_shared<TcpSession>(sessions, std::move(socket), std::move(peer), std::move(ticket))->run();
  };
  // Only HTTP requests name a forwarded client; the TCP port has no headers.
  listeners.http =
      listen(ioc, services, "--http", config.http, http_session, http_refusal, shares, error, &config.trusted_proxies);
  if (!listeners.http) return false;
  if (config.tcp.empty()) return true;
  listeners.tcp = listen(ioc, services, "--tcp", config.tcp, tcp_session, tcp_refusal, shares, error);
  return listeners.tcp != nullptr;
}

/// Tests and scripts read these lines to learn the ports when 0 was asked for.
void announce(const Listeners& listeners) {
  const auto http = listeners.http->local_endpoint();
  std::cout << "facewire-server listening on http://" << http.address().to_string() << ":" << http.port() << "/"
            << std::endl;
  if (!listeners.tcp) return;
  const auto tcp = listeners.tcp->local_endpoint();
  std::cout << "facewire-server tcp on tcp://" << tcp.address().to_string() << ":" << tcp.port() << std::endl;
}

void log_ready(const ServerConfig& config) {
  const char* faces = !config.physics           ? "behavior only, no physics face"
                      : config.physics_sleeps ? "physics face, asleep at rest"
                                              : "physics face, always awake";
  const char* lod = config.physics && config.physics_lod ? ", shed under load" : "";
  spdlog::info("ready: rooms tick at {} Hz on {} worker thread(s), {}{}; data in {}", config.tick_hz, config.workers,
               faces, lod, config.data);
}

/// The node's name in a cluster: --node, else the host name and HTTP port.
std::string node_name(const ServerConfig& config, unsigned short http_port) {
  if (!config.node.empty()) return config.node;
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return std::string(host) + ":" + std::to_string(http_port);
}

// What each part above the core receives of it, made once here.

ApiServices api_services(ServerCore& core) {
  return {core.config(), core.metrics(),   core.physics_lod(), core.abuse(), core.store(),
          core.rooms(),  core.own_faces(), core.server_key(),  core.state(), core.looks(),
          core.addresses(), core.workers()};
}

UploadServices upload_services(ServerCore& core) {
  return {core.config(), core.metrics(), core.abuse(), core.addresses(), core.store(), core.server_key(),
          core.state().draining};
}

ClusterServices cluster_services(ServerCore& core) {
  return {core.config(),    core.abuse(),    core.addresses(), core.tokens(),   core.store(),
          core.looks(),     core.server_key(), core.residents(), core.workers(), core.room_bus(),
          core.rooms(),     core.sessions(), core.state()};
}

/// Runs `ioc` on `threads` threads, this one included, until it stops.
void run_io_threads(net::io_context& ioc, int threads) {
  std::vector<std::thread> others;
  for (int i = 1; i < threads; ++i) others.emplace_back([&ioc] { ioc.run(); });
  ioc.run();
  for (auto& thread : others) thread.join();
}

}  // namespace

int run_network_server(const ServerConfig& config) {
  // Each connection takes a descriptor; the soft limit is often far below what the operator allows.
  const unsigned long descriptors = raise_descriptor_limit(kDescriptorsWanted);
  std::string error;
  const std::unique_ptr<ServerCore> core = ServerCore::open(config, error);
  if (!core) return cannot_start(error);
  const ApiServices api = api_services(*core);
  net::io_context ioc(config.io_threads);
  PhotoWorker photo_worker(config.landmark_model, config.photo_threads, config.abuse.photo_queue);
  PhotoPreparation photos(upload_services(*core), photo_worker);
  AvatarRepreparation repreparation(core->store(), photo_worker);
  std::set<std::string> own_faces;
  for (const StoredAvatar& face : core->own_faces()) own_faces.insert(face.asset);
  AvatarSweeper sweeper(core->store(), std::move(own_faces), config.avatar_retention_days);
  const HttpServices http{core->config(), core->metrics(), core->abuse(), core->addresses(), photos, api,
                          core->session_services()};
  Listeners listeners;
  if (!open_listeners(ioc, http, listeners, descriptors, error)) return cannot_start(error);
  std::unique_ptr<ClusterNode> cluster;
  if (!config.redis.empty()) {
    // Before the loop runs (no request is served yet): the cluster's server
    // key signs this node's avatar keys.
    RedisAddress address = *parse_redis_url(config.redis, error);  // checked with the flag
    if (!config.redis_password_file.empty()) {
      const auto password = read_redis_password_file(config.redis_password_file, error);
      if (!password) return cannot_start(error);
      address.password = *password;
    }
    if (!address.username.empty() && address.password.empty())
      return cannot_start("--redis names a user but no password: add it to the URL (USER:PASSWORD@) or give "
                          "--redis-password-file");
    cluster = std::make_unique<ClusterNode>(cluster_services(*core), ioc.get_executor(), address,
                                            node_name(config, listeners.http->local_endpoint().port()));
    cluster->start();
  }
  announce(listeners);
  core->open_demo_room();  // ready (/readyz) once listening and the lobby is seated
  log_ready(config);
  const auto drain_time = std::chrono::milliseconds(static_cast<long>(config.drain_seconds * 1000));
  DrainOnSignal drain(ioc, *core, drain_time, [&listeners] { listeners.stop_room_port(); });
  run_io_threads(ioc, config.io_threads);
  core->stop();
  if (cluster) {
    // The loop ran out: a short one of its own tells Redis this node leaves.
    ioc.restart();
    std::thread farewell([&ioc] { ioc.run_for(std::chrono::seconds(3)); });
    cluster->stop();
    ioc.stop();
    farewell.join();
  }
  spdlog::info("stopped");
  return 0;
}

}  // namespace fw::server
