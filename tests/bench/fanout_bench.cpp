#include "fanout_bench.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <nlohmann/json.hpp>

#include "bench_failure.hpp"
#include "fanout_client.hpp"
#include "fanout_servers.hpp"
#include "http_get.hpp"

namespace fw::bench {
namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;
using fanout::BenchClient;
using fanout::FanoutServers;

struct FanoutArgs {
  int rooms = 10;
  int per_room = 10;
  double seconds = 10;
  double warmup_seconds = 3;
  double room_interval = 0;  // seconds between one room's joins and the next room's
  bool json = false;
  std::string physics = "sleeping";  // sleeping, awake, off
  std::string physics_lod = "on";    // on: the server sheds physics under load (its default); off: never
  std::string solver = "projective";  // the physics face's: projective (the server's default) or massspring
  int client_threads = 1;
  int server_threads = 2;
  int server_workers = 2;
  std::string server;  // path of facewire-server; default: beside this program
  std::string nodes = "1";  // node counts, run in turn: "1", "2", "1,2", "1,2,1,2"
};

constexpr int kMaxNodes = 8;

// "1,2" -> {1, 2}; an empty vector if any item is not a count from 1 to kMaxNodes.
std::vector<int> parse_node_counts(const std::string& text) {
  std::vector<int> counts;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    if (item.empty() || item.size() > 2 || item.find_first_not_of("0123456789") != std::string::npos) return {};
    const int count = std::stoi(item);
    if (count < 1 || count > kMaxNodes) return {};
    counts.push_back(count);
  }
  if (!text.empty() && text.back() == ',') return {};
  return counts;
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

// The machine's load when a run starts: the bench shares its cores.
double load_average_1m() {
  std::ifstream in("/proc/loadavg");
  double load = -1;
  in >> load;
  return load;
}

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

// Tick-to-decode from the owner's tick: a room's frame of one tick is
// stamped by its owner for the owner's clients and later, when the faces
// arrive, by each node that bridges it. The earliest stamp of a tick among
// the room's clients is the owner's when some of them are on the owner
// (with --per-room at least --nodes every room spans the nodes, so they
// are); on one node every stamp is.
std::vector<float> latencies_from_owner_ms(const std::vector<std::shared_ptr<BenchClient>>& clients) {
  std::map<std::pair<std::string, std::uint32_t>, std::uint64_t> earliest;  // (room, tick) -> stamp
  for (const auto& client : clients)
    for (const auto& sample : client->samples()) {
      auto [it, inserted] = earliest.try_emplace({client->room(), sample.tick}, sample.stamped_us);
      if (!inserted) it->second = std::min(it->second, sample.stamped_us);
    }
  std::vector<float> latencies;
  for (const auto& client : clients)
    for (const auto& sample : client->samples()) {
      const std::uint64_t stamped = earliest.at({client->room(), sample.tick});
      if (sample.decoded_us >= stamped) latencies.push_back(static_cast<float>(sample.decoded_us - stamped) / 1000.0f);
    }
  return latencies;
}

// One run against `node_count` nodes: the JSON object of its figures.
nlohmann::json run_once(const FanoutArgs& args, int node_count) {
  const int clients = args.rooms * args.per_room;
  raise_descriptor_limit(2 * clients + 256 + 64 * node_count);
  const std::string server_binary =
      args.server.empty() ? (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "facewire-server").string()
                          : args.server;
  if (!std::filesystem::exists(server_binary)) fail_bench("fanout", server_binary + " not found; build facewire-server or pass --server");
  std::string server_args = "--no-demo-room --log-level warn --room-size " + std::to_string(args.per_room) + " --max-rooms " +
                            std::to_string(args.rooms) + " --threads " + std::to_string(args.server_threads) + " --workers " +
                            std::to_string(args.server_workers);
  // Every client runs on 127.0.0.1: what one address may do is raised to what the run needs.
  server_args += " --joins-per-minute 1000000 --room-joins-per-minute 1000000 --rooms-per-hour 1000000 --seats-per-address " +
                 std::to_string(args.per_room) + " --max-connections-per-address " + std::to_string(clients + 64) +
                 " --max-connections-per-block " + std::to_string(clients + 64) +
                 " --rooms-per-address 100000 --rooms-per-block 100000 --fresh-share-percent 0 --seats-per-block " +
                 std::to_string(args.per_room);
  if (args.physics == "awake") server_args += " --physics-always-awake";
  if (args.physics == "off") server_args += " --no-physics";
  if (args.physics_lod == "off") server_args += " --no-physics-lod";
  if (args.solver == "massspring") server_args += " --physics-mass-spring";
  auto servers = std::make_unique<FanoutServers>(server_binary, server_args, node_count);
  if (!servers->error().empty()) {
    const std::string why = servers->error();
    servers.reset();  // its processes and data directories go before the exit
    fail_bench("fanout", why);
  }
  const int nodes = servers->nodes();

  asio::io_context io;
  fanout::Totals totals;
  std::vector<std::shared_ptr<BenchClient>> all;
  std::vector<tcp::endpoint> endpoint_of;  // per client: its node
  std::vector<int> clients_on(static_cast<std::size_t>(nodes), 0);
  for (int r = 0; r < args.rooms; ++r)
    for (int i = 0; i < args.per_room; ++i) {
      // Round robin within each room, started one node further for each
      // room, so that every room spans the nodes and their first joins differ.
      const int node = (r + i) % nodes;
      ++clients_on[static_cast<std::size_t>(node)];
      endpoint_of.emplace_back(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(servers->http_port(node)));
      all.push_back(std::make_shared<BenchClient>(io, totals, "bench-" + std::to_string(r), "c" + std::to_string(i)));
    }
  auto work = asio::make_work_guard(io);
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, args.client_threads); ++t) threads.emplace_back([&io] { io.run(); });

  // Join in batches so the server's handshake time-out is never the limit.
  const auto join_start = Clock::now();
  // With --room-interval, rooms open one after another, as a cluster sees
  // them in use: each node's load (which places new rooms) is reported
  // twice a second, so rooms opened together all go to one node.
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (args.room_interval > 0 && i > 0 && i % static_cast<std::size_t>(args.per_room) == 0)
      std::this_thread::sleep_for(std::chrono::duration<double>(args.room_interval));
    asio::post(io, [client = all[i], endpoint = endpoint_of[i]] { client->start(endpoint); });
    if (i % 25 == 24) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const auto join_deadline = std::chrono::seconds(120) + std::chrono::duration<double>(args.room_interval * args.rooms);
  while (totals.joined + totals.closed < clients && Clock::now() - join_start < join_deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const double join_seconds = std::chrono::duration<double>(Clock::now() - join_start).count();
  std::this_thread::sleep_for(std::chrono::duration<double>(args.warmup_seconds));

  const double load_1m = load_average_1m();
  std::vector<double> node_cpu(static_cast<std::size_t>(nodes));
  for (int n = 0; n < nodes; ++n) node_cpu[static_cast<std::size_t>(n)] = fanout::process_cpu_seconds(servers->node_pid(n));
  const double redis_cpu_before = servers->redis_cpu_seconds();
  const double bench_cpu_before = fanout::process_cpu_seconds(::getpid());
  const auto window_start = Clock::now();
  totals.measuring = true;
  std::this_thread::sleep_for(std::chrono::duration<double>(args.seconds));
  totals.measuring = false;
  const double window = std::chrono::duration<double>(Clock::now() - window_start).count();
  double server_cpu = 0;
  for (int n = 0; n < nodes; ++n) {
    auto& cpu = node_cpu[static_cast<std::size_t>(n)];
    cpu = fanout::process_cpu_seconds(servers->node_pid(n)) - cpu;
    server_cpu += cpu;
  }
  const double redis_cpu = servers->redis_cpu_seconds() - redis_cpu_before;
  const double bench_cpu = fanout::process_cpu_seconds(::getpid()) - bench_cpu_before;

  // Per node: memory, how much physics it kept at the end of the window,
  // the rooms it owns (by Redis) and the clients it serves.
  double rss_mb = 0, rss_peak_mb = 0, physics_share = 1.0, kinematic_faces = 0;
  double frames_sent = 0, frames_shared = 0;  ///< avatar frames the nodes sent, and of them already encoded
  std::vector<int> rooms_owned(static_cast<std::size_t>(nodes), 0);
  for (int r = 0; r < args.rooms && servers->clustered(); ++r) {
    const std::string owner = servers->owner_of("bench-" + std::to_string(r));
    for (int n = 0; n < nodes; ++n)
      if (owner == servers->node_name(n)) ++rooms_owned[static_cast<std::size_t>(n)];
  }
  nlohmann::json per_node = nlohmann::json::array();
  for (int n = 0; n < nodes; ++n) {
    const auto index = static_cast<std::size_t>(n);
    const pid_t pid = servers->node_pid(n);
    const double rss = fanout::process_status_mb(pid, "VmRSS"), rss_peak = fanout::process_status_mb(pid, "VmHWM");
    const std::string metrics = test::http_get(servers->http_port(n), "/metrics").body;
    const double share = metric_value(metrics, "facewire_physics_share", 1.0);
    const double kinematic = metric_value(metrics, "facewire_kinematic_faces", 0.0);
    frames_sent += metric_value(metrics, "facewire_avatar_frames_sent_total", 0.0);
    frames_shared += metric_value(metrics, "facewire_avatar_frames_shared_total", 0.0);
    rss_mb += rss;
    rss_peak_mb += rss_peak;
    physics_share = std::min(physics_share, share);
    kinematic_faces += kinematic;
    per_node.push_back({{"node", servers->node_name(n)},
                        {"clients", clients_on[index]},
                        {"rooms_owned", servers->clustered() ? rooms_owned[index] : args.rooms},
                        {"server_cpu_pct", round2(100.0 * node_cpu[index] / window)},
                        {"server_rss_mb", round2(rss)},
                        {"physics_share_end", round2(share)}});
  }

  work.reset();
  io.stop();
  for (auto& thread : threads) thread.join();

  std::vector<float> latencies;
  std::vector<double> tick_rates;
  int held = 0;
  for (const auto& client : all) {
    for (const auto& sample : client->samples())
      latencies.push_back(static_cast<float>(sample.decoded_us - sample.stamped_us) / 1000.0f);
    if (client->open()) ++held;
    if (client->open()) tick_rates.push_back(client->tick_hz());
  }
  const std::vector<float> from_owner = latencies_from_owner_ms(all);
  std::sort(tick_rates.begin(), tick_rates.end());
  const double tick_min = tick_rates.empty() ? 0 : tick_rates.front();
  double tick_mean = 0;
  for (double rate : tick_rates) tick_mean += rate / static_cast<double>(tick_rates.size());
  const double p50 = percentile(latencies, 50), p99 = percentile(latencies, 99);
  auto latency = [](double v) { return v < 0 ? nlohmann::json(nullptr) : nlohmann::json(round2(v)); };
  // What a delivered avatar-frame costs the machine: the nodes' and Redis'
  // CPU together, so that one node and a cluster compare on one scale.
  const auto frames = static_cast<double>(totals.avatar_frames);
  const nlohmann::json cpu_per_frame =
      frames > 0 ? nlohmann::json(round2(1e6 * (server_cpu + redis_cpu) / frames)) : nlohmann::json(nullptr);

  return {
      {"nodes", nodes},
      {"rooms", args.rooms},
      {"per_room", args.per_room},
      {"seconds", round2(window)},
      {"physics", args.physics},
      {"physics_lod", args.physics_lod},
      {"solver", args.solver},
      {"physics_share_end", round2(physics_share)},
      {"kinematic_faces_end", kinematic_faces},
      // Of the avatar frames the nodes sent since they started, the share a
      // shared encoder had already made for another viewer (server/rooms/
      // shared_encoder.hpp): at most (n - 1) / n in rooms of n, each face
      // going to all n, its own person's stream included.
      {"shared_frame_share", frames_sent > 0 ? round2(frames_shared / frames_sent) : 0.0},
      {"clients", clients},
      {"clients_joined", totals.joined.load()},
      {"clients_held", held},
      {"join_seconds", round2(join_seconds)},
      {"room_interval", args.room_interval},
      {"avatar_frames_per_s", round2(frames / window)},
      {"avatar_frames_per_s_per_client", round2(frames / window / std::max(1, held))},
      {"room_frames_per_s_per_client", round2(static_cast<double>(totals.room_frames) / window / std::max(1, held))},
      {"room_tick_hz_mean", round2(tick_mean)},
      {"room_tick_hz_min", round2(tick_min)},
      {"latency_ms_p50", latency(p50)},
      {"latency_ms_p99", latency(p99)},
      {"latency_from_owner_ms_p50", latency(percentile(from_owner, 50))},
      {"latency_from_owner_ms_p99", latency(percentile(from_owner, 99))},
      {"latency_samples", latencies.size()},
      {"kbps_down_per_client", round2(static_cast<double>(totals.bytes) * 8.0 / 1000.0 / window / std::max(1, held))},
      {"decode_errors", totals.decode_errors.load()},
      {"close_reasons", totals.close_reasons()},
      {"server_cpu_pct", round2(100.0 * server_cpu / window)},
      {"redis_cpu_pct", round2(100.0 * redis_cpu / window)},
      {"cpu_us_per_avatar_frame", cpu_per_frame},
      {"server_rss_mb", round2(rss_mb)},
      {"server_rss_peak_mb", round2(rss_peak_mb)},
      {"bench_cpu_pct", round2(100.0 * bench_cpu / window)},
      {"per_node", per_node},
      {"load_1m", round2(load_1m)},
      {"cores", std::thread::hardware_concurrency()},
  };
}

// The mean of `key` over the runs with `nodes` nodes; 0 if none has it.
double mean_over_runs(const nlohmann::json& runs, int nodes, const char* key) {
  double sum = 0;
  int count = 0;
  for (const auto& run : runs)
    if (run.at("nodes") == nodes && run.at(key).is_number()) {
      sum += run.at(key).get<double>();
      ++count;
    }
  return count ? sum / count : 0;
}

void run(const FanoutArgs& args) {
  const std::vector<int> counts = parse_node_counts(args.nodes);
  nlohmann::json out;
  if (counts.size() == 1) {
    out = run_once(args, counts.front());
  } else {
    // Side by side: each count in the order given (repeats allowed, to
    // alternate on a busy machine), and how the CPU per delivered
    // avatar-frame of the most nodes compares with that of the fewest.
    nlohmann::json runs = nlohmann::json::array();
    for (const int nodes : counts) runs.push_back(run_once(args, nodes));
    const auto [fewest, most] = std::minmax_element(counts.begin(), counts.end());
    const double base = mean_over_runs(runs, *fewest, "cpu_us_per_avatar_frame");
    const double scaled = mean_over_runs(runs, *most, "cpu_us_per_avatar_frame");
    out = {{"runs", runs},
           {"cpu_per_frame_ratio",
            *fewest != *most && base > 0 ? nlohmann::json(std::round(scaled / base * 1000.0) / 1000.0) : nlohmann::json(nullptr)}};
  }
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
  cmd->add_option("--room-interval", args->room_interval,
                  "seconds between the joins of one room and the next (0: all rooms at once)")
      ->check(CLI::Range(0.0, 60.0))
      ->capture_default_str();
  cmd->add_option("--physics", args->physics, "sleeping (faces at rest stop stepping), awake (always step), off")
      ->check(CLI::IsMember({"sleeping", "awake", "off"}))
      ->capture_default_str();
  cmd->add_option("--physics-lod", args->physics_lod,
                  "on: the server sheds physics when its ticks run late (its default); off: it never does")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--solver", args->solver, "the physics face's solver: projective (the server's default) or massspring")
      ->check(CLI::IsMember({"massspring", "projective"}))
      ->capture_default_str();
  cmd->add_option("--client-threads", args->client_threads, "threads running the clients")->check(CLI::Range(1, 16))->capture_default_str();
  cmd->add_option("--server-threads", args->server_threads, "the server's --threads")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--server-workers", args->server_workers, "the server's --workers")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--server", args->server, "facewire-server to run (default: the one beside this program)");
  cmd->add_option("--nodes", args->nodes,
                  "nodes: 1 is one process without Redis; N >= 2 starts a redis-server and N cluster nodes with the "
                  "clients of every room spread over them; a list (1,2) runs each in turn and prints them side by side")
      ->check([](const std::string& text) {
        return parse_node_counts(text).empty()
                   ? "'" + text + "' is not a node count from 1 to " + std::to_string(kMaxNodes) +
                         " or a comma-separated list of them (e.g. 1,2)"
                   : std::string();
      })
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
