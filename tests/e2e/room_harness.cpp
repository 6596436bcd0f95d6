#include "room_harness.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <thread>

#include <gtest/gtest.h>

#include "fw/model/file_io.hpp"
#include "http_get.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/image_codec.hpp"
#include "room_layout.hpp"

namespace fw::test {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("facewire-e2e-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

RoomServer::RoomServer(const std::string& extra_args) {
  data_ = fresh_directory("server-data");
  // Every client here runs on 127.0.0.1: what one address may do is raised.
  process_ = std::make_unique<ServerProcess>(
      bin("facewire-server"), "--tcp 127.0.0.1:0 --data " + data_.string() +
                                  " --no-demo-room --log-level warn --joins-per-minute 100000 --room-joins-per-minute 100000 --rooms-per-hour 100000"
                                  " --chat-per-minute 100000 --seats-per-address 64 --seats-per-block 64 --rooms-per-address 100000 --rooms-per-block 100000 " +
                                  extra_args);
  // The second line names the TCP port: "facewire-server tcp on tcp://ADDR:PORT".
  const std::string line = process_->port() > 0 ? process_->next_stdout_line(30000) : "";
  const auto colon = line.rfind(':');
  if (line.find("tcp://") != std::string::npos && colon != std::string::npos) tcp_port_ = std::atoi(line.c_str() + colon + 1);
}

bool RoomServer::wait_for_room(const std::string& room, int avatars, double timeout_s) const {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto reply = http_get(http_port(), "/api/rooms");
    const auto json = nlohmann::json::parse(reply.body, nullptr, false);
    if (json.is_object() && json.contains("rooms"))
      for (const auto& entry : json["rooms"])
        if (entry.value("name", "") == room && entry.value("avatars", 0) >= avatars) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

RoomServer::~RoomServer() {
  process_.reset();
  std::filesystem::remove_all(data_);
}

ClientRun::ClientRun(const std::string& name, const std::string& args) : name_(name) {
  stderr_path_ = std::filesystem::temp_directory_path() / ("facewire-e2e-client-" + name + "-" + std::to_string(::getpid()) + ".log");
  const std::string command = bin("facewire-client") + " join " + args + " --json 2>" + stderr_path_.string();
  // A client runs for its --seconds (60 at most in these tests), then ends.
  future_ = std::async(std::launch::async, [command] { return run_command(command, false, 150); });
}

ClientRun::~ClientRun() {
  wait();
  std::filesystem::remove(stderr_path_);
}

void ClientRun::wait() {
  if (waited_) return;
  waited_ = true;
  result_ = future_.get();
  status_ = result_.status;
  // The summary is the last line of stdout.
  std::string last;
  std::istringstream lines(result_.output);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) last = line;
  summary_ = nlohmann::json::parse(last, nullptr, false);
  if (summary_.is_discarded()) summary_ = nlohmann::json::object();
}

std::string ClientRun::transcript() const {
  std::ifstream in(stderr_path_);
  std::stringstream err;
  err << in.rdbuf();
  return "client " + name_ + " (status " + std::to_string(status_) + ")\nstdout: " + result_.output +
         "\nstderr (tail): " + err.str().substr(err.str().size() > 4000 ? err.str().size() - 4000 : 0);
}

std::string astronaut_photo() {
  return test_photo("astronaut.png");
}

std::string astronaut_package() {
  // Made once, removed when the test program ends.
  struct Package {
    std::filesystem::path path;
    Package() {
      path = std::filesystem::temp_directory_path() / ("facewire-e2e-astronaut-" + std::to_string(::getpid()) + ".fwa");
      if (run_command(bin("facewire-server") + " prep " + astronaut_photo() + " -o " + path.string()).status != 0) path.clear();
    }
    ~Package() {
      if (!path.empty()) std::filesystem::remove(path);
    }
  };
  static const Package package;
  return package.path.string();
}

std::vector<std::filesystem::path> frame_files(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(directory)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().extension() == ".png") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

model::RgbaImage read_png(const std::filesystem::path& path) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  model::RgbaImage image;
  if (!model::read_file(path.string(), 64 << 20, bytes, error) || !render::decode_image(bytes, 4096, image, error))
    ADD_FAILURE() << path << ": " << error;
  return image;
}

bool shows_faces_at_every_seat(const model::RgbaImage& image, int count) {
  const render::RendererOptions defaults;
  const glm::vec3 background = defaults.background * 255.0f;
  const auto camera = client::room_camera(count, static_cast<float>(image.width) / static_cast<float>(image.height));
  for (const glm::mat4& place : client::room_places(count)) {
    const glm::vec3 centre = render::project_to_pixel(camera, client::face_centre(place), image.width, image.height);
    int face_pixels = 0, total = 0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) {
        const int x = static_cast<int>(centre.x) + dx, y = static_cast<int>(centre.y) + dy;
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
        ++total;
        const std::uint8_t* p = image.at(x, y);
        const float difference = std::abs(p[0] - background.r) + std::abs(p[1] - background.g) + std::abs(p[2] - background.b);
        face_pixels += difference > 30.0f ? 1 : 0;
      }
    if (total == 0 || face_pixels * 4 < total * 3) return false;
  }
  return true;
}

std::vector<double> seat_changes(const model::RgbaImage& a, const model::RgbaImage& b, int count) {
  std::vector<double> changes;
  if (a.width != b.width || a.height != b.height) return changes;
  const auto camera = client::room_camera(count, static_cast<float>(a.width) / static_cast<float>(a.height));
  for (const glm::mat4& place : client::room_places(count)) {
    const glm::vec3 centre = render::project_to_pixel(camera, client::face_centre(place), a.width, a.height);
    double sum = 0;
    int samples = 0;
    for (int dy = -8; dy <= 8; ++dy)
      for (int dx = -8; dx <= 8; ++dx) {
        const int x = static_cast<int>(centre.x) + dx, y = static_cast<int>(centre.y) + dy;
        if (x < 0 || y < 0 || x >= a.width || y >= a.height) continue;
        for (int c = 0; c < 3; ++c) sum += std::abs(a.at(x, y)[c] - b.at(x, y)[c]);
        samples += 3;
      }
    changes.push_back(samples ? sum / samples : 0);
  }
  return changes;
}

}  // namespace fw::test
