#pragma once
// One subscriber of `facewire-bench fanout`: a real WebSocket client that
// joins a room, decodes every room frame as a thin client would, and adds
// what it received to the run's totals while the window is open.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "fw/codec/codec.hpp"

namespace fw::bench::fanout {

/// What every client adds to while the window is open.
struct Totals {
  std::atomic<bool> measuring{false};
  std::atomic<std::uint64_t> avatar_frames{0}, room_frames{0}, bytes{0}, decode_errors{0};
  std::atomic<int> joined{0}, closed{0};

  /// Why clients closed: the server's closing reason, or the step that
  /// failed (connect, handshake, read, write) with its error. A run that
  /// seats fewer clients than it asked for says why in its JSON.
  void note_close(const std::string& why);
  std::map<std::string, int> close_reasons() const;

 private:
  mutable std::mutex reasons_mutex_;
  std::map<std::string, int> reasons_;
};

/// Microseconds of the steady clock: the server stamps ticks with the same
/// host's monotonic clock, so tick-to-decode is a difference of the two.
std::uint64_t steady_now_us();

/// Hello (timestamps on, packages off), then every room frame decoded, and
/// the delay from the server's tick to the decode recorded.
class BenchClient : public std::enable_shared_from_this<BenchClient> {
 public:
  BenchClient(boost::asio::io_context& io, Totals& totals, std::string room, std::string name);

  void start(const boost::asio::ip::tcp::endpoint& server);

  /// A room frame decoded while measuring: the room's tick, the time the
  /// node that sent it stamped on it, and when it was decoded here. On a
  /// node that bridges a room owned elsewhere the stamp is that node's (when
  /// the owner's faces reached it), not the owner's tick.
  struct Sample {
    std::uint32_t tick;
    std::uint64_t stamped_us, decoded_us;
  };
  /// Samples taken while measuring; read after the io_context stopped.
  const std::vector<Sample>& samples() const { return samples_; }
  const std::string& room() const { return room_; }
  /// The room's tick rate seen by this client in the window.
  double tick_hz() const;
  bool open() const { return !closed_; }

 private:
  template <class Message>
  void send(const Message& message);
  void send_bytes(std::shared_ptr<std::vector<std::uint8_t>> bytes);
  void write_next();
  void ping();
  void read();
  void on_message(std::span<const std::uint8_t> message, std::size_t n);
  /// Closes the client, counting `why` (Totals::note_close).
  void close(const std::string& why);

  static constexpr std::size_t kMaxSamples = 4000;
  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::asio::steady_timer ping_timer_;
  Totals& totals_;
  std::string room_, name_;
  boost::beast::flat_buffer buffer_;
  std::vector<std::shared_ptr<std::vector<std::uint8_t>>> outbox_;
  codec::RoomDecoder decoder_;
  std::vector<Sample> samples_;
  std::uint32_t pings_ = 0;
  std::uint32_t first_tick_ = 0, last_tick_ = 0;
  std::uint64_t first_tick_time_us_ = 0, last_tick_time_us_ = 0;
  bool closed_ = false, resync_sent_ = false;
};

}  // namespace fw::bench::fanout
