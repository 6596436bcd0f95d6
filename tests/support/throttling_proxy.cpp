#include "throttling_proxy.hpp"

#include <algorithm>
#include <deque>
#include <functional>
#include <future>

#include <boost/asio/connect.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

namespace fw::test {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

// Counters of one direction, summed over connections; read by the test thread.
struct ThrottlingProxy::Direction {
  mutable std::mutex mutex;
  LinkCounters counters;
  std::deque<std::pair<Clock::time_point, std::size_t>> recent_reads;  // the last second's reads
  std::uint64_t recent_bytes = 0;

  void offered(Clock::time_point now, std::size_t bytes, Clock::duration queueing) {
    std::lock_guard lock(mutex);
    counters.bytes_in += bytes;
    recent_reads.emplace_back(now, bytes);
    recent_bytes += bytes;
    while (!recent_reads.empty() && now - recent_reads.front().first >= std::chrono::seconds(1)) {
      recent_bytes -= recent_reads.front().second;
      recent_reads.pop_front();
    }
    counters.max_bytes_offered_per_second = std::max(counters.max_bytes_offered_per_second, recent_bytes);
    counters.max_queueing =
        std::max(counters.max_queueing, std::chrono::duration_cast<std::chrono::milliseconds>(queueing));
  }
  void delivered(std::size_t bytes) {
    std::lock_guard lock(mutex);
    counters.bytes_out += bytes;
  }
  void queue_full() {
    std::lock_guard lock(mutex);
    ++counters.queue_full_events;
  }
};

// One direction of one connection: reads from `from`, holds each packet
// until the link would have delivered it, writes it to `to`. Not in an
// anonymous namespace: ThrottlingProxy::Connection, which the header
// names, holds two.
class ProxyPipe : public std::enable_shared_from_this<ProxyPipe> {
 public:
  ProxyPipe(tcp::socket& from, tcp::socket& to, const LinkShape& shape,
            std::shared_ptr<ThrottlingProxy::Direction> counters, std::function<void()> on_close)
      : from_(from), to_(to), shape_(shape), counters_(std::move(counters)), on_close_(std::move(on_close)),
        read_timer_(from.get_executor()), write_timer_(from.get_executor()) {
    buffer_.resize(std::max<std::size_t>(1, shape_.packet_bytes));
  }

  void start() { read(); }

 private:
  // Bytes read but not yet serialised onto the link.
  double backlog_bytes(Clock::time_point now) const {
    const double seconds = std::chrono::duration<double>(serial_end_ - now).count();
    return std::max(0.0, seconds) * shape_.bits_per_second / 8.0;
  }

  void read() {
    const auto now = Clock::now();
    if (backlog_bytes(now) >= static_cast<double>(shape_.queue_bytes)) {
      // The queue is full: stop reading (the sender's TCP window fills up)
      // until a packet's worth of room is free again.
      counters_->queue_full();
      const double free_at_s =
          static_cast<double>(shape_.queue_bytes - std::min(shape_.queue_bytes, buffer_.size())) * 8.0 /
          shape_.bits_per_second;
      read_timer_.expires_at(serial_end_ - std::chrono::duration_cast<Clock::duration>(
                                               std::chrono::duration<double>(free_at_s)));
      read_timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) {
        if (!ec) self->read();
      });
      return;
    }
    from_.async_read_some(asio::buffer(buffer_), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
      self->on_read(ec, n);
    });
  }

  void on_read(boost::system::error_code ec, std::size_t n) {
    if (ec) {
      source_ended_ = true;
      if (ec != asio::error::eof) return finish();
      return write();  // deliver what is queued, then pass the end on
    }
    const auto now = Clock::now();
    const auto serial_start = std::max(now, serial_end_);
    serial_end_ = serial_start + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(static_cast<double>(n) * 8.0 / shape_.bits_per_second));
    counters_->offered(now, n, serial_start - now);
    queue_.push_back({std::vector<std::uint8_t>(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(n)),
                      serial_end_ + shape_.delay});
    write();
    read();
  }

  void write() {
    if (writing_) return;
    if (queue_.empty()) {
      if (source_ended_) {
        boost::system::error_code ignored;
        to_.shutdown(tcp::socket::shutdown_send, ignored);
        finish();
      }
      return;
    }
    writing_ = true;
    write_timer_.expires_at(queue_.front().deliver_at);
    write_timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) {
      if (ec) return;
      asio::async_write(self->to_, asio::buffer(self->queue_.front().bytes),
                        [self](boost::system::error_code write_ec, std::size_t n) {
                          self->writing_ = false;
                          if (write_ec) return self->finish();
                          self->counters_->delivered(n);
                          self->queue_.pop_front();
                          self->write();
                        });
    });
  }

  void finish() {
    if (finished_) return;
    finished_ = true;
    read_timer_.cancel();
    write_timer_.cancel();
    on_close_();
  }

  struct Packet {
    std::vector<std::uint8_t> bytes;
    Clock::time_point deliver_at;
  };
  tcp::socket& from_;
  tcp::socket& to_;
  LinkShape shape_;
  std::shared_ptr<ThrottlingProxy::Direction> counters_;
  std::function<void()> on_close_;
  asio::steady_timer read_timer_, write_timer_;
  std::vector<std::uint8_t> buffer_;
  std::deque<Packet> queue_;
  Clock::time_point serial_end_{};
  bool writing_ = false, source_ended_ = false, finished_ = false;
};

// Both sockets of one proxied connection and its two pipes. The pipes hold
// references to the sockets, so the connection outlives them: each pipe's
// close callback holds the connection.
struct ThrottlingProxy::Connection : std::enable_shared_from_this<Connection> {
  explicit Connection(tcp::socket accepted) : client(std::move(accepted)), server(client.get_executor()) {}

  void start(const tcp::endpoint& target, const LinkShape& up_shape, const LinkShape& down_shape,
             std::shared_ptr<Direction> up, std::shared_ptr<Direction> down) {
    boost::system::error_code ec;
    server.open(target.protocol(), ec);
    // A small receive window toward the server, so that a full queue here
    // pushes back on the server within a few kilobytes instead of the
    // megabytes loopback allows.
    server.set_option(asio::socket_base::receive_buffer_size(static_cast<int>(down_shape.queue_bytes)), ec);
    server.async_connect(target, [self = shared_from_this(), up_shape, down_shape, up, down](boost::system::error_code connect_ec) {
      if (connect_ec) return self->close();
      auto closer = [self] { self->pipe_closed(); };
      self->up_pipe = std::make_shared<ProxyPipe>(self->client, self->server, up_shape, up, closer);
      self->down_pipe = std::make_shared<ProxyPipe>(self->server, self->client, down_shape, down, closer);
      self->up_pipe->start();
      self->down_pipe->start();
    });
  }

  void pipe_closed() {
    if (++closed_pipes == 2) close();
  }

  void close() {
    boost::system::error_code ignored;
    client.close(ignored);
    server.close(ignored);
    up_pipe.reset();  // breaks the cycle connection -> pipe -> callback -> connection
    down_pipe.reset();
  }

  tcp::socket client, server;
  std::shared_ptr<ProxyPipe> up_pipe, down_pipe;
  int closed_pipes = 0;
};

ThrottlingProxy::ThrottlingProxy(const std::string& target_host, int target_port, const LinkShape& up,
                                 const LinkShape& down, int listen_port)
    : acceptor_(io_, tcp::endpoint(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(listen_port))),
      target_(asio::ip::make_address(target_host == "localhost" ? "127.0.0.1" : target_host),
              static_cast<unsigned short>(target_port)),
      up_shape_(up), down_shape_(down), up_(std::make_shared<Direction>()), down_(std::make_shared<Direction>()) {
  port_ = acceptor_.local_endpoint().port();
  accept();
  thread_ = std::thread([this] { io_.run(); });
}

ThrottlingProxy::~ThrottlingProxy() {
  // Close everything on the proxy's own thread, then stop it: the handlers
  // left behind hold only closed sockets.
  std::promise<void> closed;
  asio::post(io_, [this, &closed] {
    boost::system::error_code ignored;
    acceptor_.close(ignored);
    std::lock_guard lock(connections_mutex_);
    for (const auto& weak : connections_)
      if (auto connection = weak.lock()) connection->close();
    closed.set_value();
  });
  closed.get_future().wait();
  io_.stop();
  thread_.join();
}

void ThrottlingProxy::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (ec) return;
    auto connection = std::make_shared<Connection>(std::move(socket));
    {
      std::lock_guard lock(connections_mutex_);
      std::erase_if(connections_, [](const auto& weak) { return weak.expired(); });
      connections_.push_back(connection);
    }
    connection->start(target_, up_shape_, down_shape_, up_, down_);
    accept();
  });
}

void ThrottlingProxy::drop_connections() {
  std::vector<std::weak_ptr<Connection>> connections;
  {
    std::lock_guard lock(connections_mutex_);
    connections.swap(connections_);
  }
  asio::post(io_, [connections] {
    for (const auto& weak : connections)
      if (auto connection = weak.lock()) connection->close();
  });
}

LinkCounters ThrottlingProxy::up() const {
  std::lock_guard lock(up_->mutex);
  return up_->counters;
}

LinkCounters ThrottlingProxy::down() const {
  std::lock_guard lock(down_->mutex);
  return down_->counters;
}

}  // namespace fw::test
