#pragma once
// A slow link on loopback for tests: a TCP proxy that carries each direction
// at a fixed bit rate with a fixed one-way delay, as a 9.6 kbit/s modem link
// with 300 ms of latency would (tc netem is not available on the test
// machines). Bytes wait in a bounded queue, as in a router: when the queue is
// full the proxy stops reading, so TCP's back-pressure reaches the sender.
//
// It runs its own io_context on one thread; one proxy serves any number of
// connections, each with links of its own.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

namespace fw::test {

/// One direction of the link.
struct LinkShape {
  double bits_per_second = 9600;                 ///< serialisation rate, > 0
  std::chrono::milliseconds delay{300};          ///< one-way propagation delay
  std::size_t queue_bytes = 16 * 1024;           ///< bytes waiting to be serialised before reading stops
  std::size_t packet_bytes = 128;                ///< largest piece read and forwarded at once
};

/// What one direction carried, over all connections.
struct LinkCounters {
  std::uint64_t bytes_in = 0;   ///< read from the sender
  std::uint64_t bytes_out = 0;  ///< delivered to the receiver
  /// The most bytes the sender offered within any one-second window (read
  /// times, before the rate limit): what the sender tried to push.
  std::uint64_t max_bytes_offered_per_second = 0;
  /// The longest a byte waited in the queue before its serialisation began.
  std::chrono::milliseconds max_queueing{0};
  /// How often the queue was full and reading paused (back-pressure).
  std::uint64_t queue_full_events = 0;
};

class ThrottlingProxy {
 public:
  /// Listens on 127.0.0.1:listen_port (0: a free port) and forwards every
  /// connection to target_host:target_port, shaping client->target as `up`
  /// and target->client as `down`. Throws if it cannot listen.
  ThrottlingProxy(const std::string& target_host, int target_port, const LinkShape& up, const LinkShape& down,
                  int listen_port = 0);
  ~ThrottlingProxy();
  ThrottlingProxy(const ThrottlingProxy&) = delete;
  ThrottlingProxy& operator=(const ThrottlingProxy&) = delete;

  int port() const { return port_; }
  LinkCounters up() const;
  LinkCounters down() const;
  /// Closes every connection it carries (both ends), as a dropped link
  /// would; it keeps accepting new ones.
  void drop_connections();

  struct Direction;  // shared with the connection objects in the .cpp
 private:
  struct Connection;
  void accept();

  boost::asio::io_context io_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::ip::tcp::endpoint target_;
  LinkShape up_shape_, down_shape_;
  std::shared_ptr<Direction> up_, down_;
  std::mutex connections_mutex_;
  std::vector<std::weak_ptr<Connection>> connections_;
  int port_ = 0;
  std::thread thread_;
};

}  // namespace fw::test
