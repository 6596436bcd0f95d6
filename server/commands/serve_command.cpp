#include "serve_command.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "endpoint.hpp"
#include "fw/photo/photo_limits.hpp"
#include "logging.hpp"
#include "network_server.hpp"
#include "redis_url.hpp"
#include "server_config.hpp"

namespace fw::server {
namespace {

/// An ADDR:PORT flag checked while the command line is read, so that a bad
/// address is a usage error that names its flag; empty passes (off).
CLI::Validator endpoint_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return {};
        std::string error;
        return parse_endpoint(text, error) ? std::string() : error;
      },
      "ADDR:PORT");
}

void add_address_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--http", config.http, "HTTP and WebSocket address, ADDR:PORT (port 0: any free port)")
      ->envname("FACEWIRE_HTTP")
      ->check(endpoint_check())
      ->capture_default_str();
  cmd.add_option("--tcp", config.tcp, "length-prefixed TCP address for native clients, ADDR:PORT (default: off)")
      ->envname("FACEWIRE_TCP")
      ->check(endpoint_check());
  cmd.add_option("--data", config.data, "directory of the avatar store")
      ->envname("FACEWIRE_DATA")
      ->capture_default_str();
}

void add_thread_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--threads", config.io_threads, "I/O threads")
      ->envname("FACEWIRE_THREADS")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd.add_option("--workers", config.workers, "threads that tick rooms and encode streams")
      ->envname("FACEWIRE_WORKERS")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd.add_option("--speech-threads", config.speech_threads,
                 "threads that make chat lines' lip-sync tracks (espeak-ng), shared by every room")
      ->check(CLI::Range(1, 8))
      ->capture_default_str();
  cmd.add_option("--speech-queue", config.speech_queue,
                 "chat lines that may wait for a speech thread; a line past them is shown but not said")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
}

void add_room_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--tick-hz", config.tick_hz, "simulation and send ticks per second")
      ->check(CLI::Range(1, 60))
      ->capture_default_str();
  cmd.add_option("--room-size", config.room_size, "avatars per room, the room's own included")
      ->envname("FACEWIRE_ROOM_SIZE")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd.add_option("--max-rooms", config.max_rooms, "rooms at once")->check(CLI::Range(1, 100000))->capture_default_str();
  cmd.add_option_function<double>(
         "--idle-seat-seconds",
         [&config](double seconds) {
           config.timeouts.idle_person = std::chrono::milliseconds(static_cast<long>(seconds * 1000));
         },
         "a person who neither sends (pings aside) nor reads for this long is let go, and their seat and a room "
         "only they hold with them (default " +
             std::to_string(std::chrono::seconds(limits::kIdlePersonTimeout).count()) + ")")
      ->check(CLI::Range(0.1, 86400.0));
  cmd.add_flag("!--no-demo-room", config.demo_room, "do not open the demo room 'lobby'");
  cmd.add_option("--max-previews", config.previews.max, "face-lab previews at once on the server")
      ->check(CLI::Range(std::size_t{0}, std::size_t{100'000}))
      ->capture_default_str();
  cmd.add_option("--previews-per-address", config.previews.per_address, "face-lab previews at once from one address")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1'000}))
      ->capture_default_str();
  cmd.add_option_function<long>(
         "--preview-idle-seconds", [&config](long seconds) { config.previews.idle = std::chrono::seconds(seconds); },
         "a face-lab preview whose page changes nothing for this long ends (default " +
             std::to_string(config.previews.idle.count()) + ")")
      ->check(CLI::Range(1L, 86400L));
}

void add_limit_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--default-client-bps", config.default_client_bps,
                 "downstream budget of a client that states none, bit/s")
      ->check(CLI::Range(2400u, 100'000'000u))
      ->capture_default_str();
  cmd.add_option("--max-client-bps", config.max_client_bps, "the most any client is sent, bit/s")
      ->check(CLI::Range(2400u, 100'000'000u))
      ->capture_default_str();
  cmd.add_option("--max-upload-bytes", config.max_upload_bytes, "largest photo or package upload")
      ->check(CLI::Range(std::size_t{1024}, std::size_t{64} * 1024 * 1024))
      ->capture_default_str();
  cmd.add_option("--avatar-retention-days", config.avatar_retention_days,
                 "delete uploaded avatars and their photos after this many days without a use; 0: keep them until "
                 "their uploader deletes them")
      ->check(CLI::Range(0u, 36500u))
      ->capture_default_str();
  cmd.add_option("--min-upload-bytes-per-second", config.min_upload_bytes_per_second,
                 "an upload's body, once started, must bring this many bytes a second over each 5 s (the first "
                 "5 s free), else 408; 0: no pace, 15 s for the whole body")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1'000'000'000}))
      ->capture_default_str();
  cmd.add_option("--max-photo-pixels", config.max_photo_pixels,
                 "photos whose header declares more pixels are refused (413) before they are decoded")
      ->check(CLI::Range(std::size_t{10'000}, photo::kMaxPhotoPixels))
      ->capture_default_str();
  cmd.add_option("--auth-secret", config.auth_secret, "require join tokens signed with this secret")
      ->envname("FACEWIRE_AUTH_SECRET");
  cmd.add_option("--metrics-secret", config.metrics_secret,
                 "/metrics answers only 'Authorization: Bearer SECRET' (with --auth-secret and none: closed)")
      ->envname("FACEWIRE_METRICS_SECRET");
}

void add_cluster_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--redis", config.redis,
                 "join a cluster on this Redis: redis://[USER[:PASSWORD]@]HOST[:PORT][/DB] (server/CLUSTER.md); none: one process")
      ->envname("FACEWIRE_REDIS")
      ->check([](const std::string& url) {
        std::string error;
        return parse_redis_url(url, error) ? std::string() : error;
      });
  cmd.add_option("--redis-password-file", config.redis_password_file,
                 "read the Redis password (or the ACL user's, with redis://USER@HOST) from this file's first line")
      ->envname("FACEWIRE_REDIS_PASSWORD_FILE")
      ->check([](const std::string& path) {
        std::string error;
        return read_redis_password_file(path, error) ? std::string() : error;
      });
  cmd.add_option("--node", config.node, "this node's name in the cluster (default: the host name and HTTP port)")
      ->envname("FACEWIRE_NODE")
      ->check([](const std::string& name) {
        if (name.empty() || name.size() > 64) return std::string("a node name is 1 to 64 characters");
        for (const char c : name)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' && c != ':')
            return std::string("a node name is letters, digits and - _ . : only");
        return std::string();
      });
  cmd.add_option_function<double>(
         "--rejoin-grace",
         [&config](double seconds) { config.rejoin_grace = std::chrono::milliseconds(static_cast<long>(seconds * 1000)); },
         "seconds a room's new owner keeps the seat of a person whose node died (default 30)")
      ->check(CLI::Range(1.0, 3600.0));
}

/// A rate flag in events a minute (or an hour), kept as a token bucket's
/// rate a second; the burst stays the default's, or one second of the rate
/// when that is more: events that come together (a thousand clients of one
/// address joining within a few seconds, their hellos read in bunches while
/// the server is busy) could never use a rate above its burst a second.
void add_rate_flag(CLI::App& cmd, const std::string& flag, BucketRate& rate, double per, const std::string& what) {
  cmd.add_option_function<double>(
         flag,
         [&rate, per, default_burst = rate.burst](double n) {
           rate.per_second = n / per;
           rate.burst = std::max(default_burst, rate.per_second);
         },
         what + " (default " + std::to_string(static_cast<int>(rate.per_second * per + 0.5)) + ", burst " +
             std::to_string(static_cast<int>(rate.burst)) + ")")
      ->check(CLI::Range(0.01, 1e7));
}

void add_address_limit_flags(CLI::App& cmd, ServerConfig& config) {
  AbuseLimits& abuse = config.abuse;
  cmd.add_option("--max-connections", config.max_connections,
                 "connections open at once on each port (fewer if the open-files limit allows fewer)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000}))
      ->capture_default_str();
  cmd.add_option("--max-connections-per-address", abuse.connections_per_address,
                 "connections open at once from one address (IPv6: one /64)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000}))
      ->capture_default_str();
  add_rate_flag(cmd, "--joins-per-minute", abuse.joins, 60, "room joins from one address a minute");
  add_rate_flag(cmd, "--chat-per-minute", abuse.chat, 60, "chat lines from one address a minute");
  add_rate_flag(cmd, "--room-chat-per-minute", abuse.room_chat, 60, "chat lines into one room a minute");
  add_rate_flag(cmd, "--scripts-per-minute", abuse.scripts, 60, "face scripts (FACS commands) from one address a minute");
  add_rate_flag(cmd, "--room-joins-per-minute", abuse.room_joins, 60, "joins into one room a minute, from everyone");
  add_rate_flag(cmd, "--uploads-per-minute", abuse.uploads, 60, "uploads from one address a minute");
  add_rate_flag(cmd, "--rooms-per-hour", abuse.room_creations, 3600, "rooms one address may create an hour");
  cmd.add_option("--max-connections-per-block", abuse.connections_per_block,
                 "connections open at once on each port from one network block (IPv4 /24, IPv6 /48)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000}))
      ->capture_default_str();
  cmd.add_option("--rooms-per-address", abuse.rooms_per_address, "rooms open at once that one address opened")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000}))
      ->capture_default_str();
  cmd.add_option("--rooms-per-block", abuse.rooms_per_block,
                 "rooms open at once that one network block (IPv4 /24, IPv6 /48) opened")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000}))
      ->capture_default_str();
  cmd.add_option("--fresh-share-percent", abuse.fresh_share_percent,
                 "percent of rooms and of each port's connections kept for networks that hold none")
      ->check(CLI::Range(std::size_t{0}, std::size_t{50}))
      ->capture_default_str();
  cmd.add_option("--seats-per-address", abuse.seats_per_address,
                 "seats one address may hold in one room (0: half the room size)")
      ->capture_default_str();
  cmd.add_option("--seats-per-block", abuse.seats_per_block,
                 "seats one network block (IPv4 /24, IPv6 /48) may hold in one room (0: three quarters of the room "
                 "size)")
      ->capture_default_str();
  cmd.add_option("--photo-queue", abuse.photo_queue, "photos waiting to be prepared before uploads get 503")
      ->check(CLI::Range(std::size_t{1}, std::size_t{10'000}))
      ->capture_default_str();
}

/// --trusted-proxy: repeatable, and comma-separated in the environment and
/// the config file; each range is checked while the command line is read.
void add_proxy_flags(CLI::App& cmd, ServerConfig& config) {
  const CLI::Validator range_check(
      [](std::string& text) -> std::string {
        std::string error;
        return parse_address_range(text, error) ? std::string() : error;
      },
      "CIDR");
  cmd.add_option_function<std::vector<std::string>>(
         "--trusted-proxy",
         [&config](const std::vector<std::string>& ranges) {
           std::string error;
           for (const auto& range : ranges) config.trusted_proxies.add(range, error);  // checked above
         },
         "a proxy in front of the server, ADDR/PREFIX (repeatable): connections from it count against the "
         "address its X-Forwarded-For names (default: none)")
      ->envname("FACEWIRE_TRUSTED_PROXY")
      ->delimiter(',')
      ->check(range_check);
}

void add_simulation_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_flag("!--no-physics", config.physics, "drive faces by behavior only (no physics face)");
  cmd.add_flag("!--physics-always-awake", config.physics_sleeps, "faces at rest keep stepping (for benchmarks)");
  cmd.add_flag("!--physics-mass-spring", config.physics_projective,
               "solve the physics face by mass-spring sub-steps (about 4x the cost of the default, projective "
               "dynamics)");
  cmd.add_flag("!--no-physics-lod", config.physics_lod,
               "never shed physics under load (rooms then tick late instead; for benchmarks)");
}

void add_operation_flags(CLI::App& cmd, ServerConfig& config) {
  cmd.add_option("--drain-seconds", config.drain_seconds, "on SIGTERM, how long connections get to leave")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd.add_option("--landmark-model", config.landmark_model, "dlib 68-point model for photo uploads")
      ->envname("FACEWIRE_LANDMARK_MODEL");
  cmd.add_option("--photo-threads", config.photo_threads,
                 "photos prepared at once (one address's photos take turns on one; each thread after the first "
                 "loads its own landmark model, about 100 MB, when it is first needed)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{64}))
      ->capture_default_str();
  cmd.add_option("--log-level", config.log_level, "trace, debug, info, warn, error")
      ->envname("FACEWIRE_LOG_LEVEL")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
      ->capture_default_str();
  cmd.add_flag("--log-json", config.log_json, "log JSON lines")->envname("FACEWIRE_LOG_JSON");
}

/// Says whose forwarding headers count, so that an operator sees a proxy missing from the list.
void log_trusted_proxies(const TrustedProxies& proxies) {
  if (proxies.empty()) return;
  std::string ranges;
  for (const auto& range : proxies.ranges()) ranges += (ranges.empty() ? "" : ", ") + range.to_string();
  spdlog::info("client addresses: X-Forwarded-For (or Forwarded) of connections from {}", ranges);
}

}  // namespace

CLI::App* add_serve_command(CLI::App& app) {
  auto config = std::make_shared<ServerConfig>();
  CLI::App* cmd = app.add_subcommand("serve", "Run the facewire server (the default: flags alone serve too)");
  // The file is read by the top-level app (CLI11 applies config files there,
  // before subcommand callbacks); fallthrough lets `serve --config F` reach it.
  // Keys go under a [serve] section and are the long flag names.
  app.set_config("--config", "", "read options from a TOML or INI file: a [serve] section of long flag names");
  cmd->fallthrough();
  add_address_flags(*cmd, *config);
  add_thread_flags(*cmd, *config);
  add_room_flags(*cmd, *config);
  add_limit_flags(*cmd, *config);
  add_address_limit_flags(*cmd, *config);
  add_proxy_flags(*cmd, *config);
  add_cluster_flags(*cmd, *config);
  add_simulation_flags(*cmd, *config);
  add_operation_flags(*cmd, *config);
  cmd->callback([config] {
    configure_logging(config->log_level, config->log_json);
    log_trusted_proxies(config->trusted_proxies);
    std::exit(run_network_server(*config));
  });
  return cmd;
}

}  // namespace fw::server
