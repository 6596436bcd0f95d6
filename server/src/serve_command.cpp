#include "serve_command.hpp"

#include <iostream>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <spdlog/spdlog.h>

#include "endpoint.hpp"
#include "listener.hpp"

namespace fw::server {
namespace {

struct ServeArgs {
  std::string http = "127.0.0.1:8080";
  int threads = 2;
  std::string log_level = "info";
};

int serve(const ServeArgs& args) {
  std::string error;
  const auto endpoint = parse_endpoint(args.http, error);
  if (!endpoint) {
    std::cerr << "facewire-server: --http " << error << "\n";
    return 2;
  }
  spdlog::set_level(spdlog::level::from_str(args.log_level));

  boost::asio::io_context ioc(args.threads);
  boost::beast::error_code ec;
  auto listener = std::make_shared<Listener>(ioc, *endpoint, ec);
  if (ec) {
    std::cerr << "facewire-server: cannot listen on " << args.http << ": " << ec.message()
              << " (is another server using the port? choose another with --http ADDR:PORT)\n";
    return 2;
  }
  listener->run();
  const auto bound = listener->local_endpoint();
  // Tests and scripts read this line to learn the port when 0 was asked for.
  std::cout << "facewire-server listening on http://" << bound.address().to_string() << ":" << bound.port()
            << "/" << std::endl;

  boost::asio::signal_set signals(ioc, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code&, int signal) {
    spdlog::info("signal {}: stopping", signal);
    listener->stop();
    ioc.stop();
  });

  std::vector<std::thread> workers;
  for (int i = 1; i < args.threads; ++i) workers.emplace_back([&ioc] { ioc.run(); });
  ioc.run();
  for (auto& worker : workers) worker.join();
  spdlog::info("stopped");
  return 0;
}

}  // namespace

CLI::App* add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand("serve", "Run the facewire server (the default)");
  cmd->add_option("--http", args->http, "HTTP address and port, ADDR:PORT (port 0: any free port)")
      ->envname("FACEWIRE_HTTP")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "I/O threads")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--log-level", args->log_level, "trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
      ->capture_default_str();
  cmd->callback([args] { std::exit(serve(*args)); });
  return cmd;
}

}  // namespace fw::server
