#include "fanout_bench.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"
#include "http_get.hpp"
#include "server_process.hpp"
#include "bench_failure.hpp"

namespace fw::bench {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

struct FanoutArgs {
  int rooms = 10;
  int per_room = 10;
  double seconds = 10;
  double warmup_seconds = 3;
  bool json = false;
  std::string physics = "sleeping";  // sleeping, awake, off
  std::string physics_lod = "on";    // on: the server sheds physics under load (its default); off: never
  int client_threads = 1;
  int server_threads = 2;
  int server_workers = 2;
  std::string server;  // path of facewire-server; default: beside this program
};

std::uint64_t now_us() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count());
}

// What every client adds to while the window is open.
struct Totals {
  std::atomic<bool> measuring{false};
  std::atomic<std::uint64_t> avatar_frames{0}, room_frames{0}, bytes{0}, decode_errors{0};
  std::atomic<int> joined{0}, closed{0};
};

// One WebSocket subscriber: hello (timestamps on, packages off), then it
// decodes every room frame as a thin client would, and records the delay
// from the server's tick to the decode (the same host's monotonic clock).
class BenchClient : public std::enable_shared_from_this<BenchClient> {
 public:
  BenchClient(asio::io_context& io, Totals& totals, std::string room, std::string name)
      : ws_(asio::make_strand(io)), ping_timer_(ws_.get_executor()), totals_(totals), room_(std::move(room)),
        name_(std::move(name)) {}

  void start(const tcp::endpoint& server) {
    beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(30));
    beast::get_lowest_layer(ws_).async_connect(server, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return self->close();
      beast::get_lowest_layer(self->ws_).expires_never();
      self->ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::client));
      self->ws_.read_message_max(codec::kMaxDownstreamMessageBytes);
      self->ws_.binary(true);
      self->ws_.async_handshake("127.0.0.1", "/", [self](beast::error_code handshake_ec) {
        if (handshake_ec) return self->close();
        codec::Hello hello;
        hello.room = self->room_;
        hello.name = self->name_;
        hello.timestamps = true;
        hello.no_packages = true;
        self->send(hello);
        self->read();
        self->ping();
      });
    });
  }

  // Samples taken while measuring; read after the io_context stopped.
  const std::vector<float>& latencies_ms() const { return latencies_ms_; }
  // The room's tick rate seen by this client in the window.
  double tick_hz() const {
    if (last_tick_time_us_ <= first_tick_time_us_) return 0;
    return static_cast<double>(last_tick_ - first_tick_) * 1e6 / static_cast<double>(last_tick_time_us_ - first_tick_time_us_);
  }
  bool open() const { return !closed_; }

 private:
  template <class Message>
  void send(const Message& message) {
    auto bytes = std::make_shared<std::vector<std::uint8_t>>();
    codec::write_message(message, *bytes);
    send_bytes(bytes);
  }
  void send_bytes(std::shared_ptr<std::vector<std::uint8_t>> bytes) {
    // Upstream messages are rare (hello, a ping every 15 s, resyncs): one at
    // a time is enough; a message offered while one is in flight waits.
    outbox_.push_back(std::move(bytes));
    if (outbox_.size() == 1) write_next();
  }
  void write_next() {
    if (outbox_.empty() || closed_) return;
    ws_.async_write(asio::buffer(*outbox_.front()), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->outbox_.erase(self->outbox_.begin());
      self->write_next();
    });
  }

  void ping() {
    ping_timer_.expires_after(std::chrono::seconds(15));
    ping_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->closed_) return;
      self->send(codec::Ping{++self->pings_, now_us()});
      self->ping();
    });
  }

  void read() {
    buffer_.clear();
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t n) {
      if (ec) return self->close();
      const auto data = self->buffer_.cdata();
      self->on_message({static_cast<const std::uint8_t*>(data.data()), data.size()}, n);
      self->read();
    });
  }

  void on_message(std::span<const std::uint8_t> message, std::size_t n) {
    const bool measuring = totals_.measuring.load(std::memory_order_relaxed);
    if (measuring) totals_.bytes += n;
    switch (codec::classify(message)) {
      case codec::MessageKind::stream_header: {
        codec::StreamOptions options;
        if (codec::read_stream_header(message, options) == codec::DecodeError::ok) decoder_ = codec::RoomDecoder(options);
        return;
      }
      case codec::MessageKind::session:
        break;
      default:
        return;
    }
    switch (codec::session_type(message)) {
      case codec::MessageType::welcome:
        ++totals_.joined;
        return;
      case codec::MessageType::closing:
        return close();
      case codec::MessageType::timed_room_frame: {
        codec::TimedRoomFrame timed;
        if (codec::read_message(message, timed) != codec::MessageError::ok) return;
        const auto result = decoder_.decode(timed.room_frame);
        const std::uint64_t decoded_us = now_us();
        if (!measuring) return;
        ++totals_.room_frames;
        for (const auto& [id, error] : result.avatars) {
          if (error == codec::DecodeError::ok) ++totals_.avatar_frames;
          else ++totals_.decode_errors;
        }
        if (latencies_ms_.size() < kMaxSamples && decoded_us >= timed.server_time_us)
          latencies_ms_.push_back(static_cast<float>(decoded_us - timed.server_time_us) / 1000.0f);
        if (first_tick_time_us_ == 0) {
          first_tick_ = timed.tick;
          first_tick_time_us_ = timed.server_time_us;
        }
        last_tick_ = timed.tick;
        last_tick_time_us_ = timed.server_time_us;
        const auto needed = decoder_.needing_key_frames();
        if (!needed.empty() && !resync_sent_) {
          resync_sent_ = true;  // once: the server answers with key frames
          auto bytes = std::make_shared<std::vector<std::uint8_t>>();
          codec::write_resync_request(needed, *bytes);
          send_bytes(bytes);
        }
        return;
      }
      default:
        return;
    }
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    ++totals_.closed;
    ping_timer_.cancel();
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  static constexpr std::size_t kMaxSamples = 4000;
  websocket::stream<beast::tcp_stream> ws_;
  asio::steady_timer ping_timer_;
  Totals& totals_;
  std::string room_, name_;
  beast::flat_buffer buffer_;
  std::vector<std::shared_ptr<std::vector<std::uint8_t>>> outbox_;
  codec::RoomDecoder decoder_;
  std::vector<float> latencies_ms_;
  std::uint32_t pings_ = 0;
  std::uint32_t first_tick_ = 0, last_tick_ = 0;
  std::uint64_t first_tick_time_us_ = 0, last_tick_time_us_ = 0;
  bool closed_ = false, resync_sent_ = false;
};

// CPU seconds (user + system) of a process, from /proc/PID/stat.
double cpu_seconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = stat.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return 0;
  std::istringstream fields(stat.substr(close + 2));
  std::string field;
  double utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stod(field);
    if (i == 15) stime = std::stod(field);
  }
  return (utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

// A line of /proc/PID/status in megabytes (VmRSS, VmHWM).
double status_mb(pid_t pid, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;
  return 0;
}

// A sample's value from a Prometheus text exposition (`name value` lines).
double metric_value(const std::string& exposition, const std::string& name, double missing) {
  std::istringstream lines(exposition);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(name + " ", 0) == 0) return std::stod(line.substr(name.size() + 1));
  return missing;
}

double percentile(std::vector<float> values, double p) {
  if (values.empty()) return -1;
  const auto index = std::min(values.size() - 1, static_cast<std::size_t>(p / 100.0 * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
  return values[index];
}

double round2(double v) { return std::round(v * 100.0) / 100.0; }

// Room and connection counts need file descriptors: one per client here and
// one per client in the server (which inherits this limit).
void raise_descriptor_limit(int needed) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
  const rlim_t want = std::min<rlim_t>(limit.rlim_max, static_cast<rlim_t>(needed));
  if (limit.rlim_cur < want) {
    limit.rlim_cur = want;
    ::setrlimit(RLIMIT_NOFILE, &limit);
  }
  ::getrlimit(RLIMIT_NOFILE, &limit);
  if (limit.rlim_cur < static_cast<rlim_t>(needed))
    fail_bench("fanout", "needs " + std::to_string(needed) + " open files, the limit is " + std::to_string(limit.rlim_cur) +
         "; raise it (ulimit -n) or use fewer clients");
}

void run(const FanoutArgs& args) {
  const int clients = args.rooms * args.per_room;
  raise_descriptor_limit(2 * clients + 256);
  const std::string server_binary =
      args.server.empty() ? (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "facewire-server").string()
                          : args.server;
  if (!std::filesystem::exists(server_binary)) fail_bench("fanout", server_binary + " not found; build facewire-server or pass --server");
  const auto data = std::filesystem::temp_directory_path() / ("facewire-bench-fanout-" + std::to_string(::getpid()));
  std::string server_args = "--no-demo-room --log-level warn --data " + data.string() + " --room-size " +
                            std::to_string(args.per_room) + " --max-rooms " + std::to_string(args.rooms) + " --threads " +
                            std::to_string(args.server_threads) + " --workers " + std::to_string(args.server_workers);
  // Every client runs on 127.0.0.1: what one address may do is raised to what the run needs.
  server_args += " --joins-per-minute 1000000 --room-joins-per-minute 1000000 --rooms-per-hour 1000000 --seats-per-address " +
                 std::to_string(args.per_room) + " --max-connections-per-address " + std::to_string(clients + 64);
  if (args.physics == "awake") server_args += " --physics-always-awake";
  if (args.physics == "off") server_args += " --no-physics";
  if (args.physics_lod == "off") server_args += " --no-physics-lod";
  test::ServerProcess server(server_binary, server_args);
  if (server.port() == 0) fail_bench("fanout", "facewire-server did not start (" + server_binary + " " + server_args + ")");
  const pid_t server_pid = server.pid();

  asio::io_context io;
  Totals totals;
  std::vector<std::shared_ptr<BenchClient>> all;
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port()));
  for (int r = 0; r < args.rooms; ++r)
    for (int i = 0; i < args.per_room; ++i)
      all.push_back(std::make_shared<BenchClient>(io, totals, "bench-" + std::to_string(r), "c" + std::to_string(i)));
  auto work = asio::make_work_guard(io);
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, args.client_threads); ++t) threads.emplace_back([&io] { io.run(); });

  // Join in batches so the server's handshake time-out is never the limit.
  const auto join_start = Clock::now();
  for (std::size_t i = 0; i < all.size(); ++i) {
    asio::post(io, [client = all[i], endpoint] { client->start(endpoint); });
    if (i % 25 == 24) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  while (totals.joined + totals.closed < clients && Clock::now() - join_start < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const double join_seconds = std::chrono::duration<double>(Clock::now() - join_start).count();
  std::this_thread::sleep_for(std::chrono::duration<double>(args.warmup_seconds));

  const double cpu_before = cpu_seconds(server_pid), bench_cpu_before = cpu_seconds(::getpid());
  const auto window_start = Clock::now();
  totals.measuring = true;
  std::this_thread::sleep_for(std::chrono::duration<double>(args.seconds));
  totals.measuring = false;
  const double window = std::chrono::duration<double>(Clock::now() - window_start).count();
  const double server_cpu = cpu_seconds(server_pid) - cpu_before, bench_cpu = cpu_seconds(::getpid()) - bench_cpu_before;
  const double rss_mb = status_mb(server_pid, "VmRSS"), rss_peak_mb = status_mb(server_pid, "VmHWM");
  // How much physics the server kept at the end of the window.
  const std::string metrics = test::http_get(server.port(), "/metrics").body;
  const double physics_share = metric_value(metrics, "facewire_physics_share", 1.0);
  const double kinematic_faces = metric_value(metrics, "facewire_kinematic_faces", 0.0);

  work.reset();
  io.stop();
  for (auto& thread : threads) thread.join();

  std::vector<float> latencies;
  std::vector<double> tick_rates;
  int held = 0;
  for (const auto& client : all) {
    latencies.insert(latencies.end(), client->latencies_ms().begin(), client->latencies_ms().end());
    if (client->open()) ++held;
    if (client->open()) tick_rates.push_back(client->tick_hz());
  }
  std::sort(tick_rates.begin(), tick_rates.end());
  const double tick_min = tick_rates.empty() ? 0 : tick_rates.front();
  double tick_mean = 0;
  for (double rate : tick_rates) tick_mean += rate / static_cast<double>(tick_rates.size());
  const double p50 = percentile(latencies, 50), p99 = percentile(latencies, 99);
  auto latency = [](double v) { return v < 0 ? nlohmann::json(nullptr) : nlohmann::json(round2(v)); };

  const nlohmann::json out = {
      {"rooms", args.rooms},
      {"per_room", args.per_room},
      {"seconds", round2(window)},
      {"physics", args.physics},
      {"physics_lod", args.physics_lod},
      {"physics_share_end", round2(physics_share)},
      {"kinematic_faces_end", kinematic_faces},
      {"clients", clients},
      {"clients_joined", totals.joined.load()},
      {"clients_held", held},
      {"join_seconds", round2(join_seconds)},
      {"avatar_frames_per_s", round2(static_cast<double>(totals.avatar_frames) / window)},
      {"avatar_frames_per_s_per_client", round2(static_cast<double>(totals.avatar_frames) / window / std::max(1, held))},
      {"room_frames_per_s_per_client", round2(static_cast<double>(totals.room_frames) / window / std::max(1, held))},
      {"room_tick_hz_mean", round2(tick_mean)},
      {"room_tick_hz_min", round2(tick_min)},
      {"latency_ms_p50", latency(p50)},
      {"latency_ms_p99", latency(p99)},
      {"latency_samples", latencies.size()},
      {"kbps_down_per_client", round2(static_cast<double>(totals.bytes) * 8.0 / 1000.0 / window / std::max(1, held))},
      {"decode_errors", totals.decode_errors.load()},
      {"server_cpu_pct", round2(100.0 * server_cpu / window)},
      {"server_rss_mb", round2(rss_mb)},
      {"server_rss_peak_mb", round2(rss_peak_mb)},
      {"bench_cpu_pct", round2(100.0 * bench_cpu / window)},
      {"cores", std::thread::hardware_concurrency()},
  };
  std::filesystem::remove_all(data);
  if (args.json) {
    std::cout << out.dump() << std::endl;
  } else {
    std::cout << out.dump(2) << std::endl;
  }
}

}  // namespace

void add_fanout_bench(CLI::App& app) {
  auto args = std::make_shared<FanoutArgs>();
  CLI::App* cmd = app.add_subcommand("fanout", "Rooms of real WebSocket clients on loopback: frames, latency, server cost");
  cmd->add_option("--rooms", args->rooms, "rooms")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--per-room", args->per_room, "clients per room")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--seconds", args->seconds, "length of the measured window")->check(CLI::Range(0.5, 3600.0))->capture_default_str();
  cmd->add_option("--warmup", args->warmup_seconds, "seconds between the last join and the window")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--physics", args->physics, "sleeping (faces at rest stop stepping), awake (always step), off")
      ->check(CLI::IsMember({"sleeping", "awake", "off"}))
      ->capture_default_str();
  cmd->add_option("--physics-lod", args->physics_lod,
                  "on: the server sheds physics when its ticks run late (its default); off: it never does")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--client-threads", args->client_threads, "threads running the clients")->check(CLI::Range(1, 16))->capture_default_str();
  cmd->add_option("--server-threads", args->server_threads, "the server's --threads")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--server-workers", args->server_workers, "the server's --workers")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--server", args->server, "facewire-server to run (default: the one beside this program)");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
