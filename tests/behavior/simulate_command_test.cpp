// server/commands/simulate_command.cpp and render_scene_command.cpp: the commands
// run as a person runs them, on real scenes. The physics face is tested in
// tests/physics; here it is off, so these tests measure the commands.
#include "simulate_command.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fw/behavior/scene_file.hpp"
#include "fw/render/image_codec.hpp"
#include "test_paths.hpp"
#include "render_scene_command.hpp"
#include "room_simulation.hpp"
#include "run_command.hpp"

namespace fw::server {
namespace {

std::string server() { return test::bin("facewire-server"); }
std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("fw_simulate_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(SimulateCommand, RegistersBothSubcommands) {
  CLI::App app;
  add_simulate_command(app);
  add_render_scene_command(app);
  ASSERT_NE(app.get_subcommand("simulate"), nullptr);
  EXPECT_TRUE(app.get_subcommand("simulate")->get_option("--output")->get_required());
  ASSERT_NE(app.get_subcommand("render-scene"), nullptr);
}

TEST(SimulateCommand, RecordsARoomWithEventsThatReadsBack) {
  const std::string path = temp_path("room.fws");
  const auto result = test::run_command(server() + " simulate --no-physics --avatars 3 --seconds 8 --seed 5 --chat '6:2:haha :)' -o " + path + " 2>&1");
  ASSERT_EQ(result.status, 0) << result.output;
  const nlohmann::json summary = nlohmann::json::parse(result.output);
  EXPECT_EQ(summary["ticks"], 240);
  behavior::Scene scene;
  std::string error;
  ASSERT_TRUE(behavior::read_scene(path, scene, error)) << error;
  ASSERT_EQ(scene.avatars.size(), 3u);
  EXPECT_EQ(scene.tick_count(), 240u);
  EXPECT_EQ(scene.avatars[1].joined_tick, 60u);  // two seconds apart
  ASSERT_TRUE(scene.avatars[2].seat);
  EXPECT_GT(scene.avatars[2].seat->origin_mm.x, 0);
  bool leads = false, chat = false, mimics = false;
  for (const behavior::SceneEvent& e : scene.events) {
    leads |= e.avatar == 0 && e.what == "leads";
    chat |= e.avatar == 1 && e.what == "chat (joy)" && e.tick == 180;
    mimics |= e.what.find("-> mimicking (avatar-1)") != std::string::npos;
  }
  EXPECT_TRUE(leads);
  EXPECT_TRUE(chat);
  EXPECT_TRUE(mimics);
  // The same seed makes the same scene.
  const std::string again = temp_path("again.fws");
  ASSERT_EQ(test::run_command(server() + " simulate --no-physics --avatars 3 --seconds 8 --seed 5 --chat '6:2:haha :)' -o " + again + " >/dev/null").status, 0);
  std::ifstream a(path, std::ios::binary), b(again, std::ios::binary);
  EXPECT_TRUE(std::equal(std::istreambuf_iterator<char>(a), {}, std::istreambuf_iterator<char>(b)));
  std::filesystem::remove(path);
  std::filesystem::remove(again);
}

TEST(SimulateCommand, BadArgumentsSayWhatWasWrong) {
  auto r = test::run_command(server() + " simulate --avatars 0 -o /dev/null 2>&1");
  EXPECT_NE(r.status, 0);
  r = test::run_command(server() + " simulate --avatars 2 --chat 'soon:1:hi' -o /dev/null 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("SECONDS and AVATAR must be numbers"), std::string::npos) << r.output;
  r = test::run_command(server() + " simulate --avatars 2 --chat '1:7:hi' -o /dev/null 2>&1");
  EXPECT_NE(r.output.find("the avatar be 1..2"), std::string::npos) << r.output;
}

TEST(RenderSceneCommand, WritesAY4mVideoOfTheScene) {
  const std::string path = temp_path("short.fws");
  ASSERT_EQ(test::run_command(server() + " simulate --no-physics --avatars 2 --seconds 1 --join-interval 0 -o " + path + " >/dev/null").status, 0);
  const std::string video = temp_path("short.y4m");
  const auto r = test::run_command(server() + " render-scene " + path + " --y4m " + video + " --size 64x48 --every 10 2>&1");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(video, std::ios::binary);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("YUV4MPEG2 W64 H48 F3:1", 0), 0u) << header;
  // 3 frames of 64x48 4:2:0 after the header line.
  EXPECT_EQ(std::filesystem::file_size(video), header.size() + 1 + 3 * (6 + 64 * 48 * 3 / 2));
  const auto bad = test::run_command(server() + " render-scene " + path + " 2>&1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--out DIR"), std::string::npos) << bad.output;
  std::filesystem::remove(path);
  std::filesystem::remove(video);
}

// --face K: one avatar alone, facing the camera, large in the frame; each
// avatar in its own look; a face the scene does not have is named.
TEST(RenderSceneCommand, RendersOneFaceAloneFacingTheCamera) {
  const std::string path = temp_path("alone.fws");
  ASSERT_EQ(test::run_command(server() + " simulate --no-physics --avatars 3 --seconds 1 --join-interval 0 -o " + path +
                              " >/dev/null").status, 0);
  const auto centre_colour = [&](const std::string& face, double& share) {
    const std::string dir = temp_path("alone-" + face);
    const auto r = test::run_command(server() + " render-scene " + path + " --face " + face +
                                     " --out " + dir + " --size 160x120 --from 0.9 2>&1");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("alone"), std::string::npos) << r.output;
    std::ifstream file(dir + "/frame_000000.png", std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), {}};
    model::RgbaImage image;
    std::string error;
    EXPECT_TRUE(render::decode_image(bytes, 4096, image, error)) << error;
    // The middle third of the frame: how much of it is face (not the
    // renderer's background, as in a corner), and its mean colour.
    const auto colour = [&](int x, int y) {
      const std::uint8_t* p = image.at(x, y);
      return glm::dvec3(p[0], p[1], p[2]) / 255.0;
    };
    glm::dvec3 sum{};
    int face_pixels = 0, all = 0;
    const glm::dvec3 background = image.width > 0 ? colour(1, 1) : glm::dvec3{};
    for (int y = image.height / 3; y < 2 * image.height / 3; ++y)
      for (int x = image.width / 3; x < 2 * image.width / 3; ++x, ++all) {
        const glm::dvec3 c = colour(x, y);
        if (glm::length(c - background) > 0.1) {
          ++face_pixels;
          sum += c;
        }
      }
    share = all ? static_cast<double>(face_pixels) / all : 0;
    std::filesystem::remove_all(dir);
    return face_pixels ? sum / static_cast<double>(face_pixels) : glm::dvec3{};
  };
  double share0 = 0, share2 = 0;
  const glm::dvec3 first = centre_colour("0", share0), third = centre_colour("avatar-3", share2);
  EXPECT_GT(share0, 0.9) << "the face fills the middle of the frame";
  EXPECT_GT(share2, 0.9);
  EXPECT_GT(glm::length(first - third), 0.03) << "two avatars, two looks";
  const auto bad = test::run_command(server() + " render-scene " + path + " --face 7 --out " + temp_path("none") + " 2>&1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("0 avatar-1, 1 avatar-2, 2 avatar-3"), std::string::npos) << bad.output;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fw::server

namespace fw::server {
namespace {

RoomSimulation room_without_physics() {
  RoomSimulationOptions o;
  o.seed = 3;
  o.physics = false;
  return RoomSimulation(o);
}

TEST(RoomSimulation, CommandsReachTheFacesAndBadOnesSayWhy) {
  RoomSimulation room = room_without_physics();
  const AvatarId a = room.add_avatar({"a", true});
  const AvatarId b = room.add_avatar({"b", true});
  EXPECT_EQ(room.avatars(), (std::vector<AvatarId>{a, b}));
  EXPECT_NE(room.command(a, ExpressCommand{"glee", 1, 2}).find("unknown emotion"), std::string::npos);
  EXPECT_NE(room.command(a, LookAtCommand{99, 2}).find("not another face"), std::string::npos);
  EXPECT_EQ(room.command(a, FacsCommand{"BeginKeyFrame"}).rfind("script 1:1: ", 0), 0u) << "the line and column";
  ASSERT_EQ(room.command(b, ExpressCommand{"joy", 0.9f, 3}), "");
  ASSERT_EQ(room.command(a, SnubCommand{b, 5}), "");
  for (int i = 0; i < 45; ++i) room.tick();
  EXPECT_GT(room.face(b).au_intensity(12), 0.5f);  // without physics the targets show as they are
  EXPECT_TRUE(room.resting(b));
  room.remove_avatar(a);
  EXPECT_EQ(room.avatars(), (std::vector<AvatarId>{b}));
}

// The server's room (physics face and all) plays a person's vascular script
// on that person's face alone.
TEST(RoomSimulation, AVascularScriptColoursItsSendersFaceAlone) {
  std::ifstream in(fw::test::source_path("avatar/behavior/script/examples/blushing.fws"));
  const std::string blushing{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  RoomSimulationOptions o;
  o.seed = 3;
  RoomSimulation room(o);
  const AvatarId a = room.add_avatar({"a", true});
  const AvatarId b = room.add_avatar({"b", true});
  ASSERT_EQ(room.command(a, FacsCommand{blushing}), "");
  const auto cheek = static_cast<std::size_t>(codec::ColourRegion::cheek_right);
  float sender = 0, other = 0;
  for (int i = 0; i < 8 * 30; ++i) {
    room.tick();
    sender = std::max(sender, room.face(a).blush[cheek]);
    other = std::max(other, room.face(b).blush[cheek]);
  }
  EXPECT_GT(sender, 0.5f);
  EXPECT_EQ(other, 0);
}

TEST(RoomSimulation, EventsCarryTheTickTheyHappenedAt) {
  RoomSimulation room = room_without_physics();
  const AvatarId a = room.add_avatar({"a", true});
  std::vector<RoomEvent> events = room.take_events();
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[0].what, "joins");
  EXPECT_EQ(events[0].tick, 0u);
  EXPECT_EQ(events[1].what, "leads");
  EXPECT_TRUE(room.take_events().empty());
  for (int i = 0; i < 30; ++i) room.tick();
  room.chat(a, "wow!");
  room.tick();
  events = room.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().what, "chat (surprise)");
  EXPECT_EQ(events.front().tick, 30u);
  EXPECT_EQ(room.tick_index(), 31u);
}

}  // namespace
}  // namespace fw::server
