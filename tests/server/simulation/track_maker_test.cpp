// server/simulation/track_maker.hpp: a room keeps ticking while a line's
// track is being made elsewhere, and the line starts once it is back; a
// maker with no room for a line leaves it unsaid and tells the writer. The
// maker here holds the jobs until the test hands them back, as the server's
// speech worker does from its threads (tests/server/rooms/speech_worker_test.cpp).
#include "track_maker.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "room_simulation.hpp"

namespace fw::server {
namespace {

/// Keeps every job; finish() makes the oldest one's track and hands it back.
class HeldTrackMaker final : public TrackMaker {
 public:
  bool full = false;
  bool make(LineJob job, std::function<void(LineJob, LineToSay)> done) override {
    if (full) return false;
    held_.push_back({std::move(job), std::move(done)});
    return true;
  }
  std::size_t held() const { return held_.size(); }
  void finish() {
    auto [job, done] = std::move(held_.front());
    held_.erase(held_.begin());
    LineToSay line = make_line(job.text, job.language);
    done(std::move(job), std::move(line));
  }

 private:
  std::vector<std::pair<LineJob, std::function<void(LineJob, LineToSay)>>> held_;
};

struct Room {
  std::shared_ptr<HeldTrackMaker> maker = std::make_shared<HeldTrackMaker>();
  RoomSimulation simulation = [this] {
    RoomSimulationOptions o;
    o.physics = false;
    o.track_maker = maker;
    return RoomSimulation(o);
  }();
};

bool begun(const std::vector<RoomEvent>& events) {
  for (const RoomEvent& e : events)
    if (e.line) return true;
  return false;
}

TEST(TrackMaker, TheRoomTicksWhileALineIsMadeAndTheLineStartsWhenItIsBack) {
  Room room;
  const AvatarId a = room.simulation.add_avatar({"a", true, "fr"});
  room.simulation.chat(a, "nous partons demain matin");
  ASSERT_EQ(room.maker->held(), 1u);
  for (int i = 0; i < 10; ++i) room.simulation.tick();
  EXPECT_EQ(room.simulation.tick_index(), 10u) << "ticks go on while the track is made";
  EXPECT_FALSE(room.simulation.speaking(a)) << "the line waits for its track";
  EXPECT_FALSE(begun(room.simulation.take_events()));
  room.simulation.chat(a, "et nous revenons");
  EXPECT_EQ(room.maker->held(), 1u) << "one line of a face is made at a time, in order";
  room.maker->finish();
  const auto events = room.simulation.take_events();
  ASSERT_TRUE(begun(events));
  for (const RoomEvent& e : events)
    if (e.line) {
      EXPECT_EQ(e.line->frame_tick, 11u);
      EXPECT_EQ(e.line->language, "fr");
    }
  room.simulation.tick();
  EXPECT_TRUE(room.simulation.speaking(a));
  for (int i = 0; i < 30 * 10 && room.maker->held() == 0; ++i) room.simulation.tick();
  EXPECT_EQ(room.maker->held(), 1u) << "the second line is made once the first is said";
}

TEST(TrackMaker, ATrackForSomeoneGoneIsDropped) {
  Room room;
  const AvatarId a = room.simulation.add_avatar({"a", true});
  room.simulation.add_avatar({"b", true});
  room.simulation.chat(a, "wait for me");
  room.simulation.remove_avatar(a);
  room.maker->finish();
  EXPECT_FALSE(begun(room.simulation.take_events()));
}

TEST(TrackMaker, ATrackBackAfterTheRoomIsGoneIsDropped) {
  auto maker = std::make_shared<HeldTrackMaker>();
  {
    RoomSimulationOptions o;
    o.physics = false;
    o.track_maker = maker;
    RoomSimulation simulation(o);
    simulation.chat(simulation.add_avatar({"a", true}), "goodbye");
  }
  maker->finish();  // nothing to start it in, and nothing touched
  SUCCEED();
}

// A person back in a kept seat may bring another language: the lines after
// it are made in that one (OwnedRoom::take_seat_back).
TEST(TrackMaker, ALanguageChangedBetweenLinesIsTheNextLinesLanguage) {
  Room room;
  const AvatarId a = room.simulation.add_avatar({"a", true, "fr"});
  room.simulation.set_language(a, "de");
  room.simulation.chat(a, "wieder da");
  room.maker->finish();
  bool said_in_german = false;
  for (const RoomEvent& e : room.simulation.take_events())
    if (e.line) said_in_german = e.line->language == "de";
  EXPECT_TRUE(said_in_german);
}

TEST(TrackMaker, AFullMakerLeavesTheLineUnsaidAndTellsTheWriter) {
  Room room;
  room.maker->full = true;
  const AvatarId a = room.simulation.add_avatar({"a", true});
  room.simulation.chat(a, "is anyone there");
  const auto events = room.simulation.take_events();
  bool told = false;
  for (const RoomEvent& e : events) told |= e.avatar == a && e.tell.find("shown but not said") != std::string::npos;
  EXPECT_TRUE(told);
  EXPECT_FALSE(begun(events));
  room.maker->full = false;
  room.simulation.chat(a, "hello again");
  EXPECT_EQ(room.maker->held(), 1u) << "the next line is made when there is room";
}

}  // namespace
}  // namespace fw::server
