#include "serve_command.hpp"

#include <iostream>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>
#include <spdlog/spdlog.h>

#include "demo_room.hpp"
#include "endpoint.hpp"
#include "http_session.hpp"
#include "listener.hpp"
#include "logging.hpp"
#include "photo_preparation.hpp"
#include "room_registry.hpp"
#include "server_config.hpp"
#include "server_context.hpp"
#include "tcp_session.hpp"

namespace fw::server {
namespace {

namespace net = boost::asio;

std::shared_ptr<Listener> listen(net::io_context& ioc, const std::string& flag, const std::string& address,
                                 Listener::SessionFactory factory) {
  std::string error;
  const auto endpoint = parse_endpoint(address, error);
  if (!endpoint) {
    std::cerr << "facewire-server: " << flag << " " << error << "\n";
    return nullptr;
  }
  boost::beast::error_code ec;
  auto listener = std::make_shared<Listener>(ioc, *endpoint, std::move(factory), ec);
  if (ec) {
    std::cerr << "facewire-server: cannot listen on " << address << ": " << ec.message()
              << " (is another server using the port? choose another with " << flag << " ADDR:PORT)\n";
    return nullptr;
  }
  listener->run();
  return listener;
}

int serve(const ServerConfig& config) {
  configure_logging(config.log_level, config.log_json);
  ServerContext context;
  context.config = config;
  context.physics_lod.set_enabled(config.physics && config.physics_lod);
  std::string error;
  AvatarStore store(config.data, error);
  if (!error.empty()) {
    std::cerr << "facewire-server: " << error << " (choose another directory with --data DIR)\n";
    return 2;
  }
  net::io_context ioc(config.io_threads);
  net::thread_pool workers(static_cast<std::size_t>(config.workers));
  RoomRegistry rooms(context);
  PhotoPreparation photos(context);
  context.io = &ioc;
  context.workers = &workers;
  context.store = &store;
  context.rooms = &rooms;
  context.photos = &photos;
  if (!make_demo_avatars(context, error)) {
    std::cerr << "facewire-server: " << error << "\n";
    return 2;
  }

  auto http = listen(ioc, "--http", config.http, [&context](net::ip::tcp::socket&& socket, auto counter) {
    std::make_shared<HttpSession>(context, std::move(socket), std::move(counter))->run();
  });
  if (!http) return 2;
  std::shared_ptr<Listener> tcp;
  if (!config.tcp.empty()) {
    tcp = listen(ioc, "--tcp", config.tcp, [&context](net::ip::tcp::socket&& socket, auto counter) {
      boost::system::error_code ec;
      std::string peer = socket.remote_endpoint(ec).address().to_string();
      auto session = std::make_shared<TcpSession>(context, std::move(socket), std::move(peer));
      session->run();
      // Room connections are bounded by rooms x room size, not by the
      // listener's count (which limits sockets still greeting).
      --*counter;
    });
    if (!tcp) return 2;
  }
  const auto bound = http->local_endpoint();
  // Tests and scripts read this line to learn the port when 0 was asked for.
  std::cout << "facewire-server listening on http://" << bound.address().to_string() << ":" << bound.port() << "/"
            << std::endl;
  if (tcp) {
    const auto tcp_bound = tcp->local_endpoint();
    std::cout << "facewire-server tcp on tcp://" << tcp_bound.address().to_string() << ":" << tcp_bound.port()
              << std::endl;
  }
  // Ready once listening and, with a demo room, once its faces are seated.
  if (config.demo_room) open_demo_room(context, [&context] { context.ready = true; });
  else context.ready = true;
  const char* faces = !config.physics           ? "behavior only, no physics face"
                      : config.physics_sleeps ? "physics face, asleep at rest"
                                              : "physics face, always awake";
  const char* lod = config.physics && config.physics_lod ? ", shed under load" : "";
  spdlog::info("ready: rooms tick at {} Hz on {} worker thread(s), {}{}; data in {}", config.tick_hz, config.workers,
               faces, lod, config.data);

  // SIGTERM drains: no new joins, every session told to leave, then stop
  // when they are gone or the drain time is up.
  net::signal_set signals(ioc, SIGINT, SIGTERM);
  net::steady_timer drain_timer(ioc);
  const auto deadline = std::make_shared<std::chrono::steady_clock::time_point>();
  std::function<void()> check_drained = [&] {
    if (rooms.session_count() == 0 || std::chrono::steady_clock::now() > *deadline) {
      rooms.close_all_rooms();
      ioc.stop();
      return;
    }
    drain_timer.expires_after(std::chrono::milliseconds(50));
    drain_timer.async_wait([&](const boost::system::error_code& ec) {
      if (!ec) check_drained();
    });
  };
  signals.async_wait([&](const boost::system::error_code&, int signal) {
    spdlog::info("signal {}: draining {} connection(s)", signal, rooms.session_count());
    context.draining = true;
    http->stop();
    if (tcp) tcp->stop();
    *deadline = std::chrono::steady_clock::now() +
                std::chrono::milliseconds(static_cast<int>(config.drain_seconds * 1000));
    rooms.close_all_sessions();
    check_drained();
  });

  std::vector<std::thread> threads;
  for (int i = 1; i < config.io_threads; ++i) threads.emplace_back([&ioc] { ioc.run(); });
  ioc.run();
  for (auto& thread : threads) thread.join();
  workers.stop();
  workers.join();
  spdlog::info("stopped");
  return 0;
}

}  // namespace

CLI::App* add_serve_command(CLI::App& app) {
  auto config = std::make_shared<ServerConfig>();
  CLI::App* cmd = app.add_subcommand("serve", "Run the facewire server (the default)");
  // The file is read by the top-level app (CLI11 applies config files there,
  // before subcommand callbacks); fallthrough lets `serve --config F` reach it.
  // Keys go under a [serve] section and are the long flag names.
  app.set_config("--config", "", "read options from a TOML or INI file: a [serve] section of long flag names");
  cmd->fallthrough();
  cmd->add_option("--http", config->http, "HTTP and WebSocket address, ADDR:PORT (port 0: any free port)")
      ->envname("FACEWIRE_HTTP")
      ->capture_default_str();
  cmd->add_option("--tcp", config->tcp, "length-prefixed TCP address for native clients, ADDR:PORT (default: off)")
      ->envname("FACEWIRE_TCP");
  cmd->add_option("--data", config->data, "directory of the avatar store")->envname("FACEWIRE_DATA")->capture_default_str();
  cmd->add_option("--threads", config->io_threads, "I/O threads")
      ->envname("FACEWIRE_THREADS")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--workers", config->workers, "threads that tick rooms and encode streams")
      ->envname("FACEWIRE_WORKERS")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--tick-hz", config->tick_hz, "simulation and send ticks per second")
      ->check(CLI::Range(1, 60))
      ->capture_default_str();
  cmd->add_option("--room-size", config->room_size, "avatars per room, the room's own included")
      ->envname("FACEWIRE_ROOM_SIZE")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--max-rooms", config->max_rooms, "rooms at once")->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--default-client-bps", config->default_client_bps,
                  "downstream budget of a client that states none, bit/s")
      ->check(CLI::Range(2400u, 100'000'000u))
      ->capture_default_str();
  cmd->add_option("--max-client-bps", config->max_client_bps, "the most any client is sent, bit/s")
      ->check(CLI::Range(2400u, 100'000'000u))
      ->capture_default_str();
  cmd->add_option("--max-upload-bytes", config->max_upload_bytes, "largest photo or package upload")
      ->check(CLI::Range(std::size_t{1024}, std::size_t{64} * 1024 * 1024))
      ->capture_default_str();
  cmd->add_option("--auth-secret", config->auth_secret, "require join tokens signed with this secret")
      ->envname("FACEWIRE_AUTH_SECRET");
  cmd->add_flag("!--no-demo-room", config->demo_room, "do not open the demo room 'lobby'");
  cmd->add_flag("!--no-physics", config->physics, "drive faces by behavior only (no physics face)");
  cmd->add_flag("!--physics-always-awake", config->physics_sleeps, "faces at rest keep stepping (for benchmarks)");
  cmd->add_flag("!--no-physics-lod", config->physics_lod,
                "never shed physics under load (rooms then tick late instead; for benchmarks)");
  cmd->add_option("--drain-seconds", config->drain_seconds, "on SIGTERM, how long connections get to leave")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--landmark-model", config->landmark_model, "dlib 68-point model for photo uploads")
      ->envname("FACEWIRE_LANDMARK_MODEL");
  cmd->add_option("--log-level", config->log_level, "trace, debug, info, warn, error")
      ->envname("FACEWIRE_LOG_LEVEL")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
      ->capture_default_str();
  cmd->add_flag("--log-json", config->log_json, "log JSON lines")->envname("FACEWIRE_LOG_JSON");
  cmd->callback([config] { std::exit(serve(*config)); });
  return cmd;
}

}  // namespace fw::server
