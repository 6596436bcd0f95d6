// An 8-avatar room seen over a 9.6 kbit/s link with 300 ms of delay each
// way (through the throttling proxy): every avatar keeps updating, the
// stream stays within the budget, and the faces are there within 40 s.
#include <thread>

#include <gtest/gtest.h>

#include "fw/model/file_io.hpp"
#include "fw/render/image_codec.hpp"
#include "room_harness.hpp"
#include "throttling_proxy.hpp"

namespace fw::test {
namespace {

using namespace std::chrono_literals;

constexpr double kLinkBps = 9600;
constexpr int kRunSeconds = 60;

TEST(SlowLink, EightAvatarsStayAliveOverNinePointSixKbitPerSecond) {
  RoomServer server;
  ASSERT_GT(server.http_port(), 0) << "facewire-server did not start";
  const std::string package = astronaut_package();
  ASSERT_FALSE(package.empty());

  // Seven people on fast links (their faces drawn by the server from their names)...
  std::vector<std::unique_ptr<ClientRun>> others;
  for (int i = 1; i <= 7; ++i)
    others.push_back(std::make_unique<ClientRun>("p" + std::to_string(i), server.ws_url() + " --room slow --name p" +
                                                                               std::to_string(i) + " --seconds " +
                                                                               std::to_string(kRunSeconds + 20) + " -q"));
  ASSERT_TRUE(server.wait_for_room("slow", 7, 60)) << "the seven never got in";

  // ...and one behind a modem: 9.6 kbit/s and 300 ms each way, its package
  // uploaded over the same link.
  LinkShape modem;
  modem.bits_per_second = kLinkBps;
  modem.delay = 300ms;
  ThrottlingProxy proxy("127.0.0.1", server.http_port(), modem, modem);
  const auto dir = fresh_directory("modem");
  const auto start = std::chrono::steady_clock::now();
  ClientRun slow("modem", "ws://127.0.0.1:" + std::to_string(proxy.port()) + "/ --room slow --name modem --avatar " +
                              package + " --max-kbps 9.6 --seconds " + std::to_string(kRunSeconds) + " --out " +
                              dir.string() + " --fps 1 --size 320x180 --samples 0 -q");
  slow.wait();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const LinkCounters down = proxy.down();
  for (auto& other : others) other->wait();
  ASSERT_EQ(slow.status(), 0) << slow.transcript();
  const auto& summary = slow.summary();
  std::cout << "modem summary: " << summary.dump() << "\n"
            << "link down: " << down.bytes_in << " bytes offered in " << elapsed << " s, at most "
            << down.max_bytes_offered_per_second << " in one second, queueing up to " << down.max_queueing.count()
            << " ms, " << down.queue_full_events << " pauses\n";

  // Every avatar reached the modem, kept updating at 10 frames/s or more
  // (from its first frame to the end, start-up included), never stalled
  // (8 or more over the last 10 s), and was visible (its preview package
  // there) within 40 s of joining.
  ASSERT_EQ(summary.at("avatars_seen"), 8) << slow.transcript();
  for (const auto& [name, avatar] : summary.at("avatars").items()) {
    EXPECT_GE(avatar.at("fps").get<double>(), 10.0) << name << " updates too rarely\n" << slow.transcript();
    EXPECT_GE(avatar.at("fps_recent").get<double>(), 8.0) << name << " stalled at the end";
    EXPECT_LE(avatar.at("first_frame_s").get<double>(), 40.0) << name;
    ASSERT_TRUE(avatar.contains("preview_s") || avatar.contains("full_s")) << name << " never got a package";
    const double package_s = avatar.contains("preview_s") ? avatar.at("preview_s").get<double>() : avatar.at("full_s").get<double>();
    EXPECT_LE(package_s, 40.0) << name << ": its face took too long";
  }
  // The full packages follow the previews without starving the parameters
  // (the frame rates above): at least one arrived within the run.
  int full = 0;
  for (const auto& [name, avatar] : summary.at("avatars").items()) full += avatar.contains("full_s") ? 1 : 0;
  EXPECT_GE(full, 1) << slow.transcript();

  // The stream stays within its budget: what the server offered the link,
  // over the run and in its busiest second (a second's worth of queue on
  // top: the link's own buffer absorbs bursts within a second).
  const double offered_bps = static_cast<double>(down.bytes_in) * 8.0 / elapsed;
  EXPECT_LE(offered_bps, kLinkBps) << "the server sent faster than the client's budget";
  EXPECT_LE(static_cast<double>(down.max_bytes_offered_per_second) * 8.0, 2 * kLinkBps);
  EXPECT_LE(summary.at("kbps_down").get<double>(), kLinkBps / 1000.0);

  // At 40 s (one frame a second) every seat of the room of eight shows a
  // face, and every face moved in the ten seconds before.
  const auto frames = frame_files(dir);
  ASSERT_GE(frames.size(), 41u);
  const model::RgbaImage at_40 = read_png(frames[40]);
  EXPECT_TRUE(shows_faces_at_every_seat(at_40, 8)) << frames[40];
  std::vector<double> moved(8, 0.0);
  for (std::size_t i = 30; i < 40; ++i) {
    const auto changes = seat_changes(read_png(frames[i]), at_40, 8);
    for (std::size_t seat = 0; seat < changes.size(); ++seat) moved[seat] = std::max(moved[seat], changes[seat]);
  }
  for (std::size_t seat = 0; seat < moved.size(); ++seat) EXPECT_GT(moved[seat], 1.0) << "the face in seat " << seat << " stood still";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fw::test
