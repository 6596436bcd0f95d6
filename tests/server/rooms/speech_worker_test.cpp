// server/rooms/speech_worker.hpp without sockets: jobs run on its threads
// within its bound, a room's lines come back on the room's strand (and not
// at all once the room is gone), and a room goes on ticking while its line
// is being made. Also prints how long a 500-byte line takes to make.
#include "speech_worker.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <future>
#include <string>
#include <vector>

#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "room_simulation.hpp"

namespace fw::server {
namespace {

namespace net = boost::asio;
using test::eventually;

/// Holds the worker's one thread until released.
struct Gate {
  std::promise<void> opened;
  std::shared_future<void> open = opened.get_future().share();
  void block(SpeechWorker& worker) {
    std::promise<void> started;
    ASSERT_TRUE(worker.submit([open = open, &started] {
      started.set_value();
      open.wait();
    }));
    started.get_future().wait();
  }
  void release() { opened.set_value(); }
};

TEST(SpeechWorker, RunsJobsAndRefusesThosePastItsBound) {
  SpeechWorker worker(1, 2);
  Gate gate;
  gate.block(worker);
  std::atomic<int> ran{0};
  EXPECT_TRUE(worker.submit([&] { ++ran; }));
  EXPECT_TRUE(worker.submit([&] { ++ran; }));
  EXPECT_FALSE(worker.submit([&] { ++ran; })) << "two wait already";
  EXPECT_EQ(worker.queued(), 2u);
  gate.release();
  EXPECT_TRUE(eventually([&] { return ran.load() == 2; }));
  EXPECT_TRUE(worker.submit([&] { ++ran; }));
  EXPECT_TRUE(eventually([&] { return ran.load() == 3; }));
  worker.stop();
  EXPECT_FALSE(worker.submit([&] { ++ran; })) << "stopped";
}

TEST(SpeechWorker, ARoomsLineComesBackOnItsStrandWhileTheRoomLives) {
  SpeechWorker worker(1, 8);
  net::thread_pool pool(1);
  const auto strand = net::make_strand(pool.get_executor());
  std::atomic<std::uint64_t> refused{0};
  RoomTrackMaker maker(worker, strand, refused);
  auto room = std::make_shared<int>(0);
  maker.bind(room);
  std::atomic<int> on_strand{0}, elsewhere{0};
  const auto done = [&](LineJob, LineToSay line) {
    ++(strand.running_in_this_thread() && !line.mouth.empty() ? on_strand : elsewhere);
  };
  ASSERT_TRUE(maker.make({1, 1, "hello there", "en"}, done));
  EXPECT_TRUE(eventually([&] { return on_strand.load() == 1; }));
  Gate gate;
  gate.block(worker);
  ASSERT_TRUE(maker.make({1, 2, "and goodbye", "en"}, done));
  room.reset();  // the room closes while its line is made
  gate.release();
  EXPECT_TRUE(eventually([&] { return worker.queued() == 0; }));
  // The worker ends before the strand's pool, as ServerCore::stop orders
  // them: a line still being made must not reach a pool that is gone.
  worker.stop();
  pool.join();
  EXPECT_EQ(on_strand.load(), 1);
  EXPECT_EQ(elsewhere.load(), 0) << "nothing handed back to a room that is gone";
  EXPECT_EQ(refused.load(), 0u);
}

// A line that finds the queue full is refused, and counted for /metrics
// (Metrics::unsaid_lines), so that voices lost to load show.
TEST(SpeechWorker, ALineRefusedByAFullQueueIsCounted) {
  SpeechWorker worker(1, 1);
  net::thread_pool pool(1);
  std::atomic<std::uint64_t> refused{0};
  RoomTrackMaker maker(worker, net::make_strand(pool.get_executor()), refused);
  auto room = std::make_shared<int>(0);
  maker.bind(room);
  Gate gate;
  gate.block(worker);
  const auto ignore = [](LineJob, LineToSay) {};
  EXPECT_TRUE(maker.make({1, 1, "waits", "en"}, ignore));
  EXPECT_FALSE(maker.make({1, 2, "finds the queue full", "en"}, ignore));
  EXPECT_FALSE(maker.make({1, 3, "and so does this", "en"}, ignore));
  EXPECT_EQ(refused.load(), 2u);
  gate.release();
  EXPECT_TRUE(eventually([&] { return worker.queued() == 0; }));
  worker.stop();
  pool.join();
}

// The room's strand ticks on while its writer's line waits for the worker:
// the line starts once its track is back, and not before.
TEST(SpeechWorker, ARoomTicksWhileItsLineIsMade) {
  SpeechWorker worker(1, 8);
  net::thread_pool pool(1);
  auto strand = net::make_strand(pool.get_executor());
  std::atomic<std::uint64_t> refused{0};
  auto maker = std::make_shared<RoomTrackMaker>(worker, strand, refused);
  struct Room {
    RoomSimulation simulation;
  };
  auto room = std::make_shared<Room>(Room{[&] {
    RoomSimulationOptions o;
    o.physics = false;
    o.track_maker = maker;
    return RoomSimulation(o);
  }()});
  maker->bind(room);
  Gate gate;
  gate.block(worker);  // as if another room's long line were being made
  std::promise<AvatarId> seated;
  net::post(strand, [&] {
    const AvatarId a = room->simulation.add_avatar({"a", true});
    room->simulation.chat(a, "a line of many words, " + std::string(200, 'x'));
    seated.set_value(a);
  });
  const AvatarId a = seated.get_future().get();
  std::promise<std::pair<std::uint32_t, bool>> ticked;
  net::post(strand, [&] {
    for (int i = 0; i < 30; ++i) room->simulation.tick();
    ticked.set_value({room->simulation.tick_index(), room->simulation.speaking(a)});
  });
  const auto [ticks, speaking] = ticked.get_future().get();
  EXPECT_EQ(ticks, 30u) << "a second of ticks while the line waits for its track";
  EXPECT_FALSE(speaking);
  gate.release();
  std::atomic<bool> now_speaking{false};
  EXPECT_TRUE(eventually([&] {
    net::post(strand, [room, a, &now_speaking] {
      room->simulation.tick();
      now_speaking = room->simulation.speaking(a);
    });
    return now_speaking.load();
  }));
  // The worker ends before the strand's pool, as ServerCore::stop orders
  // it: its thread may still be letting go of the finished job, whose copy
  // of the strand must not outlive the pool's strand service (ASan saw it).
  worker.stop();
  pool.join();  // the ticks still posted run first: they hold the room
}

TEST(SpeechWorker, HowLongA500ByteLineTakesToMake) {
  std::string line;
  while (line.size() + 12 <= codec::kMaxChatBytes) line += "twenty-two, ";
  line.resize(codec::kMaxChatBytes, 'x');  // the longest line a person can write
  make_line(line, "en");  // espeak-ng starts and loads its voice once
  std::vector<double> ms;
  for (int i = 0; i < 5; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const LineToSay made = make_line(line, "en");
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ASSERT_FALSE(made.mouth.empty());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("{\"line_bytes\": %zu, \"make_line_ms_median\": %.1f, \"make_line_ms_max\": %.1f}\n", line.size(), ms[2],
              ms[4]);
}

}  // namespace
}  // namespace fw::server
