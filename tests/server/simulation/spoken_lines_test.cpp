// server/simulation/spoken_lines.cpp through RoomSimulation: each person's
// lines said in their own language, and the event that tells clients when a
// line begins (PROTOCOL.md 5.15). No physics face: only the timing matters.
#include "spoken_lines.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "espeak_length.hpp"
#include "room_simulation.hpp"

namespace fw::server {
namespace {

using test::espeak_track_ms;
RoomSimulation plain_room() {
  RoomSimulationOptions o;
  o.seed = 5;
  o.physics = false;
  return RoomSimulation(o);
}

/// The first "a line begins" event of `events`, if any.
std::optional<RoomEvent> line_begun(const std::vector<RoomEvent>& events) {
  for (const RoomEvent& e : events)
    if (e.line) return e;
  return std::nullopt;
}

constexpr const char* kLine = test::kLineLongerInGerman;

TEST(SpokenLines, ALineIsSaidInItsWritersLanguageWithThatLanguagesTiming) {
  RoomSimulation room = plain_room();
  const AvatarId de = room.add_avatar({"Anna", true, "de"});
  const AvatarId en = room.add_avatar({"Bob", true});  // chose none: the room's language
  room.tick();
  room.take_events();
  room.chat(de, kLine);
  room.chat(en, kLine);
  const std::vector<RoomEvent> events = room.take_events();
  const RoomEvent* german = nullptr;
  const RoomEvent* english = nullptr;
  for (const RoomEvent& e : events)
    if (e.line) (e.avatar == de ? german : english) = &e;
  ASSERT_TRUE(german && english);
  EXPECT_EQ(german->line->language, "de");
  EXPECT_EQ(english->line->language, "en");
  EXPECT_EQ(german->line->text, kLine);
  // espeak-ng's own figure for each language, within what its wave
  // generator's state changes between two syntheses (a few ms).
  const double de_ms = espeak_track_ms(kLine, "de");
  const double en_ms = espeak_track_ms(kLine, "en");
  std::printf("the same line: %u ms in German (espeak-ng %.0f), %u ms in English (espeak-ng %.0f)\n",
              german->line->duration_ms, de_ms, english->line->duration_ms, en_ms);
  EXPECT_NEAR(german->line->duration_ms, de_ms, 30.0);
  EXPECT_NEAR(english->line->duration_ms, en_ms, 30.0);
  EXPECT_GT(std::abs(de_ms - en_ms), 150.0) << "German and English say these words at different lengths";
  // The face speaks for as long as the track says.
  int ticks = 0;
  while (room.speaking(de) && ticks < 30 * 20) room.tick(), ++ticks;
  EXPECT_NEAR(ticks / 30.0 * 1000.0, german->line->duration_ms, 250.0);
}

TEST(SpokenLines, ALineBeginsInTheFrameOfTheNextTick) {
  RoomSimulation room = plain_room();
  const AvatarId a = room.add_avatar({"a", true});
  for (int i = 0; i < 3; ++i) room.tick();
  room.take_events();
  const std::uint32_t before = room.tick_index();
  room.chat(a, "see you tomorrow");
  const std::optional<RoomEvent> begun = line_begun(room.take_events());
  ASSERT_TRUE(begun);
  EXPECT_EQ(begun->avatar, a);
  EXPECT_EQ(begun->line->frame_tick, before + 1) << "the frame of the next tick carries the line's first pose";
  EXPECT_GT(begun->line->duration_ms, 500u);
  EXPECT_LE(begun->line->duration_ms, codec::kMaxSpeakingMs);
  room.tick();
  EXPECT_EQ(room.tick_index(), before + 1);
  EXPECT_TRUE(room.speaking(a));
  // The next line waits for this one and begins in a later tick's frame.
  room.chat(a, "and bring the map");
  EXPECT_FALSE(line_begun(room.take_events()));
  std::uint32_t second = 0;
  for (int i = 0; i < 30 * 10 && second == 0; ++i) {
    const std::uint32_t at = room.tick_index();
    room.tick();
    if (const std::optional<RoomEvent> e = line_begun(room.take_events())) {
      second = e->line->frame_tick;
      EXPECT_EQ(second, at + 1) << "a line started in tick() is in that tick's frame";
    }
  }
  EXPECT_GT(second, before + 1);
}

TEST(SpokenLines, ALineCutAt15SecondsTellsThePartSaid) {
  RoomSimulation room = plain_room();
  const AvatarId a = room.add_avatar({"a", true});
  std::string text;
  for (int i = 0; text.size() + 12 < codec::kMaxChatBytes; ++i) text += "twenty-two, ";
  room.chat(a, text);
  const auto events = room.take_events();
  const std::optional<RoomEvent> begun = line_begun(events);
  ASSERT_TRUE(begun);
  EXPECT_LT(begun->line->text.size(), text.size());
  EXPECT_EQ(text.rfind(begun->line->text, 0), 0u) << "the part said is the line's beginning";
  EXPECT_LE(begun->line->duration_ms, codec::kMaxSpeakingMs);
  EXPECT_GT(begun->line->duration_ms, 14'000u);
  bool told = false;
  for (const RoomEvent& e : events) told |= e.tell.find("said in part") != std::string::npos;
  EXPECT_TRUE(told);
}

TEST(SpokenLines, NothingToSayBeginsNoLine) {
  RoomSimulation room = plain_room();
  const AvatarId a = room.add_avatar({"a", true});
  room.chat(a, "🙂🙂");
  EXPECT_FALSE(line_begun(room.take_events())) << "emoji alone: no voice to keep in step with";
}

}  // namespace
}  // namespace fw::server
