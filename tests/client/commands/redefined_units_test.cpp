// A redefined action unit (server/PROTOCOL.md 5.17) as `facewire-client
// join` draws it, against a real server on loopback, as a controlled pair:
// two rooms set up alike, in each a viewer who renders frames, then anna and
// bob, who both smile (AU 12) and hold it. Only in room "redefined" has
// anna redefined AU 12, as a raise of brows and forehead far up. Above the
// eyes, where the shipped AU 12 moves nothing, the viewers' frames of anna
// differ between the rooms; of bob they do not. (The mouths would differ
// anyway: the server measures a redefined unit's face otherwise.)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "first_person_layout.hpp"
#include "fw/render/camera.hpp"
#include "room_harness.hpp"
#include "room_layout.hpp"
#include "room_test_client.hpp"

namespace fw::test {
namespace {

const char* kFrames = " --size 320x180 --fps 5 --samples 0 --max-kbps 1000 -q";
constexpr int kSeconds = 18;
constexpr int kFps = 5;

// Brows and forehead 40 units up (the most a room takes): a "smile" that
// moves what the shipped one leaves alone.
const char* kDefinition =
    "AU 12\n"
    "Above_Brow 6 0 40 0\nAbove_Brow 7 0 40 0\n"
    "Brow 3 0 40 0\nBrow 4 0 40 0\nBrow 5 0 40 0\nBrow 6 0 40 0\nBrow 7 0 40 0\nBrow 8 0 40 0\n"
    "end\n";
// AU 12 at full strength, then the same pose played for 20 s (steps of
// 0.1 s): a smile held until the viewers are done.
const char* kSmile =
    "ClearAllFrame BeginKeyFrame 12 2.0 Animate 3 \"Texture\" BeginKeyFrame 12 2.0 Animate 200 \"Texture\" end";

codec::Command facs(std::uint32_t request, const std::string& sentence) {
  codec::Command command;
  command.request_id = request;
  command.kind = codec::Command::Kind::facs;
  command.sentence = sentence;
  return command;
}

// A person of the test: a protocol client that joins and sends commands.
struct Person {
  Person(int port, const std::string& room, const std::string& name)
      : client(std::make_unique<RoomTestClient>(RoomTestClient::Transport::websocket, port)) {
    client->hello(room, name);
  }
  std::unique_ptr<RoomTestClient> client;
  std::uint32_t requests = 0;
  void say(const std::string& sentence) { client->send_message(facs(++requests, sentence)); }
  void look_at(std::uint32_t avatar) {
    codec::Command command;
    command.request_id = ++requests;
    command.kind = codec::Command::Kind::look_at;
    command.target = avatar;
    command.duration_ms = 60000;
    client->send_message(command);
  }
};

// The mean of frames [from, to) of a directory, per pixel and channel.
std::vector<double> mean_frame(const std::vector<std::filesystem::path>& files, std::size_t from, std::size_t to,
                               int& width, int& height) {
  std::vector<double> mean;
  for (std::size_t i = from; i < to; ++i) {
    const model::RgbaImage image = read_png(files[i]);
    width = image.width;
    height = image.height;
    mean.resize(static_cast<std::size_t>(width) * height * 3, 0.0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) mean[(static_cast<std::size_t>(y) * width + x) * 3 + c] += image.at(x, y)[c];
  }
  for (double& value : mean) value /= static_cast<double>(to - from);
  return mean;
}

// The mean absolute difference (0..255) of two mean frames of a room of
// three above each other face's eyes (its brows and forehead: model y 0.1
// to 0.9, eyes at y ~ 0, as client/view/room_layout.cpp places them), left
// to right as the viewer sees them.
std::array<double, 2> brow_differences(const std::vector<double>& a, const std::vector<double>& b, int width,
                                       int height) {
  const auto camera = client::room_camera(3, static_cast<float>(width) / static_cast<float>(height));
  const auto places = client::room_places(3);
  std::array<double, 2> differences{};
  for (int seat = 0; seat < 2; ++seat) {
    const auto at = [&](float x, float y) {
      return render::project_to_pixel(camera, glm::vec3(places[seat] * glm::vec4(x, y, 1.5f, 1.0f)), width, height);
    };
    const glm::vec3 top_left = at(-0.7f, 0.9f), bottom_right = at(0.7f, 0.1f);
    double sum = 0;
    int samples = 0;
    for (int y = std::max(0, static_cast<int>(top_left.y)); y <= std::min(height - 1, static_cast<int>(bottom_right.y)); ++y)
      for (int x = std::max(0, static_cast<int>(top_left.x)); x <= std::min(width - 1, static_cast<int>(bottom_right.x)); ++x)
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3 + c;
          sum += std::abs(a[i] - b[i]);
          ++samples;
        }
    differences[seat] = samples ? sum / samples : 0;
  }
  return differences;
}

TEST(RedefinedUnits, TheViewerDrawsTheRedefinedUnitOnItsPersonsFaceAlone) {
  RoomServer server;
  ASSERT_GT(server.http_port(), 0) << "facewire-server did not start";
  const auto redefined_frames = fresh_directory("units-redefined"), shipped_frames = fresh_directory("units-shipped");
  const std::string viewer = " --name cyd --seconds " + std::to_string(kSeconds) + kFrames;
  ClientRun redefined_viewer("cyd-redefined", server.ws_url() + " --room redefined --out " + redefined_frames.string() + viewer);
  ClientRun shipped_viewer("cyd-shipped", server.ws_url() + " --room shipped --out " + shipped_frames.string() + viewer);
  ASSERT_TRUE(server.wait_for_room("redefined", 1, 60)) << redefined_viewer.transcript();
  ASSERT_TRUE(server.wait_for_room("shipped", 1, 60)) << shipped_viewer.transcript();

  Person anna_redefined(server.http_port(), "redefined", "anna"), anna_shipped(server.http_port(), "shipped", "anna");
  Person bob_redefined(server.http_port(), "redefined", "bob"), bob_shipped(server.http_port(), "shipped", "bob");
  std::vector<Person*> everyone{&anna_redefined, &anna_shipped, &bob_redefined, &bob_shipped};
  for (Person* person : everyone)
    ASSERT_TRUE(person->client->pump_until([&] { return person->client->welcome.has_value(); }, std::chrono::seconds(10)));

  // Who sits where for the viewer: the same in both rooms (the same joins).
  std::vector<client::SeatedAvatar> seated;
  for (const codec::AvatarInfo& avatar : bob_redefined.client->welcome->avatars) seated.push_back({avatar.id, avatar.seat});
  std::uint32_t cyd = 0;
  for (const codec::AvatarInfo& avatar : bob_redefined.client->welcome->avatars)
    if (avatar.name == "cyd") cyd = avatar.id;
  std::uint32_t cyd_shipped = 0;
  for (const codec::AvatarInfo& avatar : bob_shipped.client->welcome->avatars)
    if (avatar.name == "cyd") cyd_shipped = avatar.id;
  const auto order = client::others_left_to_right(seated, cyd);
  ASSERT_EQ(order.size(), 2u);
  const int anna_seat = order[0] == anna_redefined.client->welcome->you ? 0 : 1;

  anna_redefined.say(kDefinition);
  ASSERT_TRUE(anna_redefined.client->pump_until([&] { return !anna_redefined.client->results.empty(); },
                                                std::chrono::seconds(10)));
  ASSERT_EQ(anna_redefined.client->results.front().error, "") << "the definition was refused";
  // Everyone looks at the viewer (so that their heads turn alike in both
  // rooms, to the camera), smiles and holds it until the viewers are done.
  for (Person* person : {&anna_redefined, &bob_redefined}) person->look_at(cyd);
  for (Person* person : {&anna_shipped, &bob_shipped}) person->look_at(cyd_shipped);
  for (Person* person : everyone) person->say(kSmile);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(kSeconds);
  while (std::chrono::steady_clock::now() < end)
    for (Person* person : everyone) person->client->pump_for(std::chrono::milliseconds(100));
  for (ClientRun* run : {&redefined_viewer, &shipped_viewer}) {
    run->wait();
    ASSERT_EQ(run->status(), 0) << run->transcript();
  }
  for (Person* person : everyone)
    for (const codec::CommandResult& result : person->client->results) EXPECT_EQ(result.error, "");

  // The last 4 seconds of each viewer's frames, averaged: blinks and
  // glances differ between the rooms, the smile they hold does not.
  const auto redefined_files = frame_files(redefined_frames), shipped_files = frame_files(shipped_frames);
  const std::size_t window = 4 * kFps;
  ASSERT_GE(redefined_files.size(), 3 * window) << redefined_viewer.transcript();
  ASSERT_GE(shipped_files.size(), 3 * window) << shipped_viewer.transcript();
  ASSERT_TRUE(shows_faces_at_every_seat(read_png(redefined_files.back()), 3));
  ASSERT_TRUE(shows_faces_at_every_seat(read_png(shipped_files.back()), 3));
  int width = 0, height = 0;
  const auto redefined_mean =
      mean_frame(redefined_files, redefined_files.size() - window, redefined_files.size(), width, height);
  const auto shipped_mean = mean_frame(shipped_files, shipped_files.size() - window, shipped_files.size(), width, height);
  const auto differences = brow_differences(redefined_mean, shipped_mean, width, height);
  const double anna = differences[anna_seat], bob = differences[1 - anna_seat];
  std::cout << "between the rooms, above the eyes: anna's face differs by " << anna << ", bob's by " << bob << "\n";
  // Seen: 14 and 0.4 with the redefined unit drawn; 0.8 and 0.6 when the
  // viewer draws the shipped AU 12 for anna too.
  EXPECT_GT(anna, 5.0) << "the viewer drew anna with the shipped AU 12";
  EXPECT_LT(bob, 2.5) << "bob's face, which nobody redefined, changed";
  EXPECT_GT(anna, 4 * bob);
  std::filesystem::remove_all(redefined_frames);
  std::filesystem::remove_all(shipped_frames);
}

}  // namespace
}  // namespace fw::test
