// Seats and attention in the room protocol (PROTOCOL.md 5.2, 5.13, 5.14):
// the welcome carries everyone's seat as the behavior laid the room out, a
// join that moves the others is followed by a seats message, and whom each
// face attends reaches every client after the welcome and then on change
// only. Driven through in-memory connections on a real worker pool.
#include <map>
#include <optional>
#include <set>

#include <gtest/gtest.h>

#include "fw/behavior/seat_layout.hpp"
#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using test::InMemoryServer;

void expect_seat(const codec::SeatInfo& got, const behavior::Seat& want) {
  // Whole millimetres and ten-thousandths of a radian on the wire.
  EXPECT_NEAR(got.x_mm, want.origin_mm.x, 0.5f);
  EXPECT_NEAR(got.y_mm, want.origin_mm.y, 0.5f);
  EXPECT_NEAR(got.z_mm, want.origin_mm.z, 0.5f);
  EXPECT_NEAR(got.facing_yaw_rad, want.facing_yaw_rad, 0.5e-4f);
}

/// The newest attention entry the inbox holds for `avatar`, if any.
template <class Peer>
std::optional<codec::Attention::Entry> latest_attention(const Peer& peer, std::uint32_t avatar) {
  std::optional<codec::Attention::Entry> latest;
  for (const auto& message : peer.attention)
    for (const auto& entry : message.entries)
      if (entry.avatar == avatar) latest = entry;
  return latest;
}

TEST(RoomSeats, TheWelcomeCarriesTheLayoutAndAJoinThatMovesTheOthersIsTold) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  ASSERT_TRUE(ann->welcome);
  ASSERT_EQ(ann->welcome->avatars.size(), 1u);
  expect_seat(ann->welcome->avatars[0].seat, behavior::seat_layout(1)[0]);

  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(bob->welcome);
  const auto two = behavior::seat_layout(2);
  ASSERT_EQ(bob->welcome->avatars.size(), 2u);
  expect_seat(bob->welcome->avatars[0].seat, two[0]);
  expect_seat(bob->welcome->avatars[1].seat, two[1]);

  // Ann sat alone facing the viewer; with Bob both moved onto the arc.
  ASSERT_TRUE(ann->read_until([&] { return !ann->seats.empty() && !ann->presence.empty(); }));
  const codec::Seats& moved = ann->seats.back();
  ASSERT_EQ(moved.seats.size(), 2u);
  for (const auto& entry : moved.seats)
    expect_seat(entry.seat, two[entry.avatar == ann->welcome->you ? 0 : 1]);
  EXPECT_EQ(ann->presence[0].avatar.name, "Bob");
  expect_seat(ann->presence[0].avatar.seat, two[1]);
  EXPECT_TRUE(ann->errors.empty()) << ann->errors.front();
}

TEST(RoomAttention, EveryoneHearsEveryFacesTargetAndThenOnlyChanges) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  const std::uint32_t ann_id = ann->welcome->you, bob_id = bob->welcome->you;
  // Right after the welcome: one message with everyone's attention.
  ASSERT_TRUE(bob->read_until([&] { return !bob->attention.empty(); }));
  std::set<std::uint32_t> first;
  for (const auto& entry : bob->attention.front().entries) first.insert(entry.avatar);
  EXPECT_EQ(first, (std::set<std::uint32_t>{ann_id, bob_id}));

  // Bob's person makes his face look at Ann: everyone hears it.
  codec::Command look;
  look.request_id = 1;
  look.kind = codec::Command::Kind::look_at;
  look.target = ann_id;
  look.duration_ms = 4000;
  bob->send(look);
  const auto bob_attends_ann = [&](const auto& peer) {
    const auto entry = latest_attention(peer, bob_id);
    return entry && entry->target == codec::AttentionTarget::avatar && entry->target_avatar == ann_id;
  };
  ASSERT_TRUE(bob->read_until([&] { return bob_attends_ann(*bob); }));
  ASSERT_TRUE(ann->read_until([&] { return bob_attends_ann(*ann); }));

  // A snub looks away from everyone.
  codec::Command snub = look;
  snub.request_id = 2;
  snub.kind = codec::Command::Kind::snub;
  bob->send(snub);
  ASSERT_TRUE(ann->read_until([&] {
    const auto entry = latest_attention(*ann, bob_id);
    return entry && entry->target == codec::AttentionTarget::nobody;
  }));

  // On change only: after the first message, no entry repeats the one
  // before it for the same face.
  std::map<std::uint32_t, codec::Attention::Entry> last;
  for (std::size_t i = 0; i < ann->attention.size(); ++i)
    for (const auto& entry : ann->attention[i].entries) {
      const auto it = last.find(entry.avatar);
      if (i > 0 && it != last.end()) {
        EXPECT_FALSE(it->second == entry) << "message " << i << " repeats avatar " << entry.avatar;
      }
      last[entry.avatar] = entry;
    }
  EXPECT_TRUE(ann->errors.empty()) << ann->errors.front();
}

}  // namespace
}  // namespace fw::server
