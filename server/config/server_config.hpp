#pragma once
// Everything `facewire-server serve` can be told, with its defaults: flags,
// FACEWIRE_* environment variables and a config file (serve_command.cpp).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "abuse_limits.hpp"
#include "server_limits.hpp"
#include "trusted_proxies.hpp"

namespace fw::server {

/// A room connection's time-outs (PROTOCOL.md, "Limits"). Not flags: the
/// protocol fixes them; tests shorten them so that they pass in a moment.
struct SessionTimeouts {
  std::chrono::milliseconds handshake = limits::kHandshakeTimeout;
  std::chrono::milliseconds idle = limits::kSessionIdleTimeout;
  std::chrono::milliseconds close = limits::kCloseTimeout;
  /// A person who neither sends anything but pings nor reads what waits
  /// for them this long is let go: a seat held for nothing
  /// (--idle-seat-seconds).
  std::chrono::milliseconds idle_person = limits::kIdlePersonTimeout;
};

/// Face-lab previews (PROTOCOL.md 5.16): each a private room of one, which
/// costs a room's tick and physics face, so they are bounded on the server
/// (--max-previews) and per address (--previews-per-address: a person with a
/// lab open in two tabs), and one whose page changes nothing for `idle`
/// (--preview-idle-seconds) ends, as a lab left open in a forgotten tab.
struct PreviewLimits {
  std::size_t max = 32;
  std::size_t per_address = 2;
  std::chrono::seconds idle{600};
};

struct ServerConfig {
  std::string http = "127.0.0.1:8080";
  std::string tcp;               ///< empty: no TCP port
  std::string data = "facewire-data";  ///< avatar store directory
  int io_threads = 2;
  int workers = 2;               ///< room ticks and encoding
  /// Threads that make chat lines' lip-sync tracks for every room
  /// (rooms/speech_worker.hpp), and the lines that may wait for them; a line
  /// that finds them all waiting is shown but not said.
  int speech_threads = 2;
  std::size_t speech_queue = 64;
  int tick_hz = 30;
  std::size_t room_size = 16;
  std::size_t max_rooms = 1000;
  /// Connections open at once on each port (ConnectionShares); fewer when
  /// the open-files limit allows fewer.
  std::size_t max_connections = limits::kMaxConnections;
  std::uint32_t default_client_bps = 64000;
  std::uint32_t max_client_bps = 1'000'000;
  std::size_t max_upload_bytes = 4 * 1024 * 1024;
  /// Avatars and their photos are deleted after this many days without a
  /// use (avatar_retention.hpp); 0 keeps them until their uploader deletes them.
  std::uint32_t avatar_retention_days = 30;
  /// Once an upload's body has started, every limits::kUploadPaceWindow must
  /// bring this many bytes a second on average; a body slower than that is
  /// answered 408 and closed. Half of the slowest link facewire serves
  /// (9.6 kbit/s, 1,200 bytes a second, over which a client uploads its
  /// package too): a dribbler that sends a byte a second is gone in 5 s, and
  /// bytes are counted as they arrive, so a slow body holds only what it
  /// sent. 0: no pace, a body's fixed limits::kUploadTimeout instead.
  std::size_t min_upload_bytes_per_second = 600;
  /// The most pixels a photo's header may declare (at most
  /// photo::kMaxPhotoPixels); a larger one is refused from its header,
  /// before it is decoded (a 12-megapixel phone photo passes; a PNG
  /// declaring 40 megapixels in a few kilobytes does not).
  std::size_t max_photo_pixels = 16 * 1000 * 1000;
  std::string auth_secret;       ///< empty: no tokens needed
  std::string metrics_secret;    ///< empty: /metrics open, unless auth_secret is set (then closed)
  bool demo_room = true;         ///< the "lobby" with three autonomous avatars
  /// Procedural faces made at start, for clients without a package (chosen
  /// by name) and the lobby's three. Not a flag; a tenth of a second each,
  /// so tests that need few make few.
  std::uint32_t demo_faces = 8;
  bool physics = true;
  bool physics_sleeps = true;
  bool physics_lod = true;       ///< shed physics (faces follow targets kinematically) when ticks run late
  /// Solve the physics face by projective dynamics (avatar/physics
  /// Solver::projective: about a quarter of mass-spring's cost per face, a
  /// little less accurate), else by mass-spring (--physics-mass-spring).
  bool physics_projective = true;
  double drain_seconds = 10;
  std::string log_level = "info";
  bool log_json = false;
  std::string landmark_model;    ///< for photo uploads; empty: the default place
  /// Photos prepared at once; each thread beyond the first loads its own
  /// landmark model (about 100 MB) when two photos are first prepared at once.
  std::size_t photo_threads = 2;
  SessionTimeouts timeouts;
  AbuseLimits abuse;             ///< per address and per room
  PreviewLimits previews;        ///< face-lab previews
  // Cluster (server/CLUSTER.md).
  std::string redis;             ///< redis://HOST:PORT[/DB]; empty: one process, no cluster
  std::string redis_password_file;  ///< the Redis password's file, instead of the URL's; empty: none
  std::string node;              ///< this node's name in the cluster; empty: the host name and port
  /// How long a room's new owner keeps the seat of a person whose node died,
  /// for them to take back with their resume key.
  std::chrono::milliseconds rejoin_grace{30'000};
  /// Peers whose X-Forwarded-For (or Forwarded) names the client that the
  /// per-address limits count (--trusted-proxy); empty: every peer is the client.
  TrustedProxies trusted_proxies;
  /// Avatar ids a room hands out (1 .. avatar_id_space - 1: the codec's 21
  /// bits), and how long an id rests after its avatar left before it is
  /// handed out again. Not flags; tests shrink them.
  std::uint32_t avatar_id_space = std::uint32_t{1} << 21;
  std::chrono::milliseconds avatar_id_quiet = limits::kAvatarIdQuiet;
};

}  // namespace fw::server
