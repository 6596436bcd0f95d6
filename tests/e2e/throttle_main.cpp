// facewire-throttle: the tests' slow link as a program, to try a client over
// a modem-like link by hand:
//   facewire-throttle --target 127.0.0.1:8080 --port 9090 --kbps 9.6 --delay-ms 300
//   facewire-client join ws://127.0.0.1:9090/ --room lobby --name me --max-kbps 9.6 --y4m - | ffplay -
#include <csignal>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "throttling_proxy.hpp"

namespace {
volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_signal(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"A TCP proxy on loopback that carries each direction at a fixed rate with a fixed delay"};
  std::string target = "127.0.0.1:8080";
  int port = 0, delay_ms = 300;
  double kbps = 9.6, up_kbps = 0;
  std::size_t queue_bytes = 16 * 1024;
  app.add_option("--target", target, "where connections go, HOST:PORT")->capture_default_str();
  app.add_option("--port", port, "loopback port to listen on (0: a free one)")->check(CLI::Range(0, 65535));
  app.add_option("--kbps", kbps, "rate of each direction, kbit/s")->check(CLI::Range(0.1, 1e6))->capture_default_str();
  app.add_option("--up-kbps", up_kbps, "client-to-target rate if different, kbit/s")->check(CLI::Range(0.0, 1e6));
  app.add_option("--delay-ms", delay_ms, "one-way delay")->check(CLI::Range(0, 10000))->capture_default_str();
  app.add_option("--queue-bytes", queue_bytes, "bytes a direction queues before it pushes back")
      ->check(CLI::Range(256, 64 << 20))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  const auto colon = target.rfind(':');
  if (colon == std::string::npos) {
    std::cerr << "facewire-throttle: --target must look like 127.0.0.1:8080\n";
    return 2;
  }
  fw::test::LinkShape down;
  down.bits_per_second = kbps * 1000;
  down.delay = std::chrono::milliseconds(delay_ms);
  down.queue_bytes = queue_bytes;
  fw::test::LinkShape up = down;
  if (up_kbps > 0) up.bits_per_second = up_kbps * 1000;
  try {
    fw::test::ThrottlingProxy proxy(target.substr(0, colon), std::stoi(target.substr(colon + 1)), up, down, port);
    std::cout << "facewire-throttle on 127.0.0.1:" << proxy.port() << " -> " << target << " (" << kbps << " kbit/s, "
              << delay_ms << " ms each way)" << std::endl;
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    while (!g_stop) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const auto d = proxy.down();
    std::cout << "carried " << d.bytes_out << " bytes down, " << proxy.up().bytes_out << " up" << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "facewire-throttle: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
