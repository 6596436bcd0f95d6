#pragma once
// What the end-to-end tests share: a real facewire-server with a TCP port,
// facewire-client processes run in the background, their JSON summaries,
// and a look at the frames they rendered.
#include <filesystem>
#include <future>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fw/model/image.hpp"
#include "run_command.hpp"
#include "server_process.hpp"

namespace fw::test {

/// A server on free loopback ports (HTTP/WebSocket and TCP) with its own
/// data directory and no demo room.
class RoomServer {
 public:
  explicit RoomServer(const std::string& extra_args = "");
  ~RoomServer();
  int http_port() const { return process_->port(); }
  int tcp_port() const { return tcp_port_; }
  std::string ws_url() const { return "ws://127.0.0.1:" + std::to_string(http_port()) + "/"; }
  std::string tcp_url() const { return "tcp://127.0.0.1:" + std::to_string(tcp_port_); }
  std::string api_url() const { return "http://127.0.0.1:" + std::to_string(http_port()); }
  /// Waits until room `room` holds at least `avatars` avatars (GET
  /// /api/rooms), at most `timeout_s`; whether it did.
  bool wait_for_room(const std::string& room, int avatars, double timeout_s) const;

 private:
  std::filesystem::path data_;
  int tcp_port_ = 0;
  std::unique_ptr<ServerProcess> process_;
};

/// A facewire-client run in the background: `join ARGS --json`, stderr kept
/// in a file for the failure message.
class ClientRun {
 public:
  ClientRun(const std::string& name, const std::string& args);
  ~ClientRun();  ///< waits, then removes the stderr file
  /// Waits for the client to end; its exit status and JSON summary.
  void wait();
  int status() const { return status_; }
  const nlohmann::json& summary() const { return summary_; }
  /// stdout and stderr, for failure messages.
  std::string transcript() const;

 private:
  std::string name_;
  std::filesystem::path stderr_path_;
  std::future<CommandResult> future_;
  CommandResult result_;
  int status_ = -1;
  nlohmann::json summary_;
  bool waited_ = false;
};

/// A package made from the astronaut portrait by `facewire-server prep`,
/// once per test program.
std::string astronaut_package();
std::string astronaut_photo();

/// The frames a client wrote with --out DIR, in order.
std::vector<std::filesystem::path> frame_files(const std::filesystem::path& directory);

/// A frame a client wrote (a failure of the test if it does not decode).
model::RgbaImage read_png(const std::filesystem::path& path);

/// Whether `image` shows a face where each of `count` room seats is
/// (client/view/room_layout): most pixels of a small patch around every
/// face's centre differ from the renderer's background.
bool shows_faces_at_every_seat(const model::RgbaImage& image, int count);

/// For each of `count` seats, the mean absolute difference (0..255) of the
/// two images in the patch around that face's centre: whether it moved.
std::vector<double> seat_changes(const model::RgbaImage& a, const model::RgbaImage& b, int count);

/// A fresh temporary directory for one test.
std::filesystem::path fresh_directory(const std::string& name);

}  // namespace fw::test
