#include "drain_on_signal.hpp"

#include <csignal>

#include <spdlog/spdlog.h>

namespace fw::server {

DrainOnSignal::DrainOnSignal(boost::asio::io_context& ioc, ServerCore& core, std::chrono::milliseconds drain_time,
                             std::function<void()> stop_accepting)
    : ioc_(ioc), core_(core), drain_time_(drain_time), stop_accepting_(std::move(stop_accepting)),
      signals_(ioc, SIGINT, SIGTERM), timer_(ioc) {
  signals_.async_wait([this](const boost::system::error_code& ec, int signal) {
    if (!ec) on_signal(signal);
  });
}

void DrainOnSignal::on_signal(int signal) {
  spdlog::info("signal {}: draining {} connection(s)", signal, core_.sessions().count());
  stop_accepting_();
  deadline_ = std::chrono::steady_clock::now() + drain_time_;
  core_.start_draining();
  stop_when_drained();
}

void DrainOnSignal::stop_when_drained() {
  if (core_.drained() || std::chrono::steady_clock::now() > deadline_) {
    ioc_.stop();
    return;
  }
  timer_.expires_after(std::chrono::milliseconds(50));
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (!ec) stop_when_drained();
  });
}

}  // namespace fw::server
