#pragma once
// SIGINT and SIGTERM drain the server instead of cutting it off: /readyz
// turns 503 (and stays reachable: the HTTP port is open until the end), the
// room port stops accepting, every session is told to leave ("shutting
// down"), and the I/O loop stops once they are gone or the drain time is up.
#include <chrono>
#include <functional>

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include "server_core.hpp"

namespace fw::server {

class DrainOnSignal {
 public:
  /// Waits for the signal on `ioc`; `stop_accepting` closes the listeners
  /// that take no part in the drain.
  DrainOnSignal(boost::asio::io_context& ioc, ServerCore& core, std::chrono::milliseconds drain_time,
                std::function<void()> stop_accepting);

 private:
  void on_signal(int signal);
  /// Stops the I/O loop once every session has left or the time is up; else looks again soon.
  void stop_when_drained();

  boost::asio::io_context& ioc_;
  ServerCore& core_;
  std::chrono::milliseconds drain_time_;
  std::function<void()> stop_accepting_;
  boost::asio::signal_set signals_;
  boost::asio::steady_timer timer_;
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace fw::server
