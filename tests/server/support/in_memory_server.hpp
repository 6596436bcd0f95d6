#pragma once
// The server core with in-memory connections, for the fast tests: the real
// rooms, subscriber streams and client sessions, on a real worker pool and a
// real I/O thread, with no socket and no process in between. Each server
// has its own data directory.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/strand.hpp>
#include <gtest/gtest.h>

#include "in_memory_session.hpp"
#include "room_inbox.hpp"
#include "server_core.hpp"
#include "server_keys.hpp"

namespace fw::test {

using namespace std::chrono_literals;
using server::InMemorySession;
using server::ServerConfig;

/// Polls `done` every millisecond until it holds or `timeout` passes.
template <class Predicate>
bool eventually(Predicate done, std::chrono::milliseconds timeout = 5s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return done();
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

struct HelloOptions {
  std::string token{};
  std::uint32_t max_bps = 0;
  bool timestamps = false;
  bool no_packages = false;
  std::string avatar{};
  /// The avatar's key; unset: the right one (InMemoryServer::join), as the uploader has it.
  std::optional<std::string> avatar_key{};
  std::string resume{};
  std::uint16_t version = codec::kProtocolVersion;  ///< 3: a client from before the speaking message
  std::string language{};
};

/// The peer of one in-memory connection: sends upstream messages and files
/// what the server wrote (RoomInbox). Hangs up when destroyed.
class InMemoryPeer : public RoomInbox {
 public:
  explicit InMemoryPeer(std::shared_ptr<InMemorySession> session) : session_(std::move(session)) {}
  ~InMemoryPeer() {
    session_->hang_up();
    eventually([&] { return session_->gone(); }, 2s);
  }
  InMemoryPeer(const InMemoryPeer&) = delete;
  InMemoryPeer& operator=(const InMemoryPeer&) = delete;

  InMemorySession& session() { return *session_; }
  const std::shared_ptr<InMemorySession>& shared_session() const { return session_; }

  template <class Message>
  void send(const Message& message) {
    session_->push_message(message);
  }
  void send_bytes(std::vector<std::uint8_t> bytes) { session_->push(std::move(bytes)); }
  void hello(const std::string& room, const std::string& name, const HelloOptions& options = {}) {
    codec::Hello h;
    h.room = room;
    h.name = name;
    h.token = options.token;
    h.max_bps = options.max_bps;
    h.timestamps = options.timestamps;
    h.no_packages = options.no_packages;
    h.avatar = options.avatar;
    h.avatar_key = options.avatar_key.value_or("");
    h.resume = options.resume;
    h.protocol_version = options.version;
    h.language = options.language;
    send(h);
  }

  /// Files everything written so far.
  void read() {
    for (const auto& message : session_->take_written()) {
      ++messages_read;
      file(*message);
    }
  }
  /// Reads until `done()` holds or `timeout` passes.
  template <class Predicate>
  bool read_until(Predicate done, std::chrono::milliseconds timeout = 5s) {
    return eventually(
        [&] {
          read();
          return done();
        },
        timeout);
  }
  void read_for(std::chrono::milliseconds duration) {
    read_until([] { return false; }, duration);
  }
  /// Reads until the server has ended the connection (a closing message, or an abort).
  bool read_until_closed(std::chrono::milliseconds timeout = 5s) {
    return read_until([&] { return session_->gone(); }, timeout);
  }

  std::uint64_t messages_read = 0;

 private:
  std::shared_ptr<InMemorySession> session_;
};

class InMemoryServer {
 public:
  /// One worker, no demo room and `faces` demo faces (each takes a tenth of
  /// a second to make): what most tests want.
  static ServerConfig test_config(std::uint32_t faces = 1) {
    ServerConfig config;
    config.workers = 1;
    config.demo_room = false;
    config.demo_faces = faces;
    // Every in-memory peer comes from one address ("in-memory"): what one
    // address may do is raised, so that a test can seat many; the tests of
    // those limits set them back.
    config.abuse.joins = config.abuse.chat = config.abuse.room_creations = config.abuse.room_joins = {1e6, 1e6};
    config.abuse.scripts = {1e6, 1e6};
    config.abuse.seats_per_address = 64;
    config.abuse.rooms_per_address = config.abuse.rooms_per_block = 100000;
    config.abuse.seats_per_block = 64;
    return config;
  }

  explicit InMemoryServer(ServerConfig config = test_config())
      : InMemoryServer(std::move(config), std::filesystem::temp_directory_path() /
                                              ("fw-in-memory-" + std::to_string(::getpid()) + "-" +
                                               std::to_string(counter_++))) {
    owns_data_ = true;
  }
  /// A server on the data directory `data` (a restart), which it leaves in
  /// place. Throws, failing the test, when the core cannot be made.
  InMemoryServer(ServerConfig config, std::filesystem::path data)
      : data_(std::move(data)), core_(open_core(with_data(std::move(config), data_))),
        work_(boost::asio::make_work_guard(io_)) {
    core_->open_demo_room();
    io_thread_ = std::thread([this] { io_.run(); });
  }
  ~InMemoryServer() {
    core_->stop();
    work_.reset();
    io_.stop();
    io_thread_.join();
    std::error_code ignored;
    if (owns_data_) std::filesystem::remove_all(data_, ignored);
  }
  InMemoryServer(const InMemoryServer&) = delete;
  InMemoryServer& operator=(const InMemoryServer&) = delete;

  server::ServerCore& core() { return *core_; }
  boost::asio::io_context& io() { return io_; }

  /// A connection whose session has started (its clock runs), not greeted
  /// yet, from the peer address `from`.
  std::unique_ptr<InMemoryPeer> connect(const std::string& from = "in-memory") {
    auto session = std::make_shared<InMemorySession>(core_->session_services(), boost::asio::make_strand(io_), from);
    session->run();
    return std::make_unique<InMemoryPeer>(std::move(session));
  }
  /// A connection that said hello and got its welcome or its closing message.
  std::unique_ptr<InMemoryPeer> join(const std::string& room, const std::string& name,
                                     const HelloOptions& options = {}) {
    auto peer = connect();
    HelloOptions with_key = options;
    if (!with_key.avatar.empty() && !with_key.avatar_key)
      with_key.avatar_key = server::avatar_key(core_->server_key(), with_key.avatar);
    peer->hello(room, name, with_key);
    peer->read_until([&] { return peer->welcome.has_value() || peer->closing.has_value(); });
    return peer;
  }

 private:
  static ServerConfig with_data(ServerConfig config, const std::filesystem::path& data) {
    config.data = data.string();
    return config;
  }
  static std::unique_ptr<server::ServerCore> open_core(const ServerConfig& config) {
    std::string error;
    auto core = server::ServerCore::open(config, error);
    if (!core) throw std::runtime_error("the server core cannot be made: " + error);
    return core;
  }

  static inline std::atomic<int> counter_{0};
  std::filesystem::path data_;
  std::unique_ptr<server::ServerCore> core_;
  boost::asio::io_context io_;
  boost::asio::executor_work_guard<boost::asio::io_context::executor_type> work_;
  std::thread io_thread_;
  bool owns_data_ = false;
};

}  // namespace fw::test
