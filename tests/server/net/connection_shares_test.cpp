// A port's places by network block without sockets (ConnectionShares):
// shares per block, the places kept for fresh blocks, which connection
// gives its place up when the port is full, and the waits refusals name.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "connection_shares.hpp"

namespace fw::server {
namespace {

using Clock = ConnectionShares::Clock;
using std::chrono::seconds;

ConnectionShareLimits shares_of(std::size_t total, std::size_t per_block, std::size_t reserve) {
  return {total, per_block, reserve};
}

std::string address_in(int block, int host) {
  return "10.0." + std::to_string(block) + "." + std::to_string(host);
}
std::string block_of(int block) { return "10.0." + std::to_string(block) + ".0/24"; }

TEST(ConnectionShares, ABlockHoldsItsShareAndNoMore) {
  ConnectionShares shares(shares_of(100, 3, 0));
  const auto now = Clock::now();
  for (int i = 0; i < 3; ++i) EXPECT_NE(shares.admit(address_in(1, i), block_of(1), now).id, 0u) << i;
  const auto refused = shares.admit(address_in(1, 9), block_of(1), now);
  EXPECT_EQ(refused.id, 0u) << "a fourth address of the same /24";
  EXPECT_EQ(refused.refusal, Abuse::block_connection_limit);
  EXPECT_NE(shares.admit(address_in(2, 1), block_of(2), now).id, 0u) << "another block has its own share";
  EXPECT_EQ(shares.held_by_block(block_of(1)), 3u);
  EXPECT_EQ(shares.open(), 4u);
}

TEST(ConnectionShares, TheLastPlacesAreForBlocksThatHoldNone) {
  ConnectionShares shares(shares_of(10, 100, 2));
  const auto now = Clock::now();
  std::vector<ConnectionShares::Id> held;
  for (int i = 0; i < 8; ++i) {
    const auto verdict = shares.admit(address_in(1, i), block_of(1), now);
    ASSERT_NE(verdict.id, 0u) << i;
    shares.busy(verdict.id, Clock::time_point::max());  // in rooms: nobody's place to take
  }
  const auto crowd = shares.admit(address_in(1, 50), block_of(1), now);
  EXPECT_EQ(crowd.id, 0u) << "8 of 10 taken: the rest is kept for fresh blocks";
  EXPECT_EQ(crowd.refusal, Abuse::connection_limit);
  EXPECT_NE(shares.admit(address_in(2, 1), block_of(2), now).id, 0u) << "a fresh block gets a kept place";
  EXPECT_EQ(shares.admit(address_in(2, 2), block_of(2), now).id, 0u) << "that block holds one now";
  EXPECT_NE(shares.admit(address_in(3, 1), block_of(3), now).id, 0u) << "another fresh block";
  EXPECT_EQ(shares.admit(address_in(4, 1), block_of(4), now).id, 0u) << "full, and nothing waits to give way";
}

TEST(ConnectionShares, AFullPortTakesThePlaceOfTheLargestBlocksLongestWaiter) {
  ConnectionShares shares(shares_of(6, 100, 0));
  auto now = Clock::now();
  std::vector<std::string> closed;
  std::vector<ConnectionShares::Id> crowd;
  for (int i = 0; i < 5; ++i) {
    const auto verdict = shares.admit(address_in(1, i), block_of(1), now);
    ASSERT_NE(verdict.id, 0u);
    shares.waiting(verdict.id, now, now + seconds(10));  // a header on its way, slowly
    shares.on_evict(verdict.id, [&closed, i] { closed.push_back(address_in(1, i)); });
    crowd.push_back(verdict.id);
    now += seconds(1);
  }
  shares.busy(crowd[0], now + seconds(15));  // its header came: it keeps its place
  const auto person = shares.admit(address_in(2, 1), block_of(2), now);  // the sixth place
  ASSERT_NE(person.id, 0u);
  EXPECT_TRUE(person.evicted.empty());
  shares.waiting(person.id, now, now + seconds(10));

  const auto late = shares.admit(address_in(1, 40), block_of(1), now);
  EXPECT_EQ(late.id, 0u) << "the crowd does not push out its own";
  EXPECT_EQ(late.refusal, Abuse::connection_limit);

  const auto second_person = shares.admit(address_in(3, 1), block_of(3), now);
  ASSERT_NE(second_person.id, 0u) << "a person from a fresh block finds a place";
  EXPECT_EQ(second_person.evicted, address_in(1, 1)) << "the crowd's longest waiter, not the busy one";
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_EQ(closed[0], address_in(1, 1));
  EXPECT_EQ(shares.open(), 6u);
  EXPECT_EQ(shares.held_by_block(block_of(1)), 4u);

  // The crowd cannot take the place of a person who waits: their block holds one.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(shares.admit(address_in(1, 60 + i), block_of(1), now).id, 0u);
  EXPECT_EQ(closed.size(), 1u);
  shares.release(crowd[1]);  // the evicted one closes at last: nothing more is freed
  EXPECT_EQ(shares.open(), 6u);
}

TEST(ConnectionShares, AnEvictionBeforeTheSessionSaysHowToCloseClosesWhenItDoes) {
  ConnectionShares shares(shares_of(2, 100, 0));
  const auto now = Clock::now();
  const auto a = shares.admit(address_in(1, 1), block_of(1), now);
  shares.admit(address_in(1, 2), block_of(1), now);
  ASSERT_NE(shares.admit(address_in(2, 1), block_of(2), now).id, 0u);
  bool closed = false;
  shares.on_evict(a.id, [&closed] { closed = true; });
  EXPECT_TRUE(closed);
}

TEST(ConnectionShares, RefusalsSayWhenThePlacesTheyWaitForFree) {
  ConnectionShares shares(shares_of(3, 2, 0));
  const auto now = Clock::now();
  const auto a = shares.admit(address_in(1, 1), block_of(1), now);
  const auto b = shares.admit(address_in(1, 2), block_of(1), now);
  const auto c = shares.admit(address_in(2, 1), block_of(2), now);
  shares.busy(a.id, now + seconds(7));
  shares.waiting(b.id, now, now + std::chrono::milliseconds(4500));
  shares.busy(c.id, now + seconds(3));
  const auto block = shares.admit(address_in(1, 3), block_of(1), now);
  EXPECT_EQ(block.refusal, Abuse::block_connection_limit);
  EXPECT_EQ(block.retry_after, seconds(5)) << "the block's earliest deadline (4.5 s, rounded up)";
  shares.busy(b.id, now + seconds(9));  // its header came
  const auto full = shares.admit(address_in(3, 1), block_of(3), now);
  EXPECT_EQ(full.refusal, Abuse::connection_limit) << "nothing waits to give its place up";
  EXPECT_EQ(full.retry_after, seconds(3)) << "the port's earliest deadline";
  EXPECT_EQ(shares.retry_for_address(address_in(1, 2), now), seconds(9));
  shares.busy(a.id, Clock::time_point::max());
  shares.busy(b.id, Clock::time_point::max());
  shares.busy(c.id, Clock::time_point::max());
  EXPECT_EQ(shares.admit(address_in(3, 1), block_of(3), now).retry_after, ConnectionShares::kUnknownWait)
      << "people in rooms have no deadline";
}

TEST(ConnectionShares, WithNoDescriptorLeftANewcomerStaysOnlyInSomeonesPlace) {
  ConnectionShares shares(shares_of(100, 100, 0));
  const auto now = Clock::now();
  for (int i = 0; i < 3; ++i) shares.admit(address_in(1, i), block_of(1), now);
  const auto crowd = shares.admit(address_in(1, 9), block_of(1), now, true);
  EXPECT_EQ(crowd.id, 0u);
  EXPECT_EQ(crowd.refusal, Abuse::descriptors_exhausted);
  const auto person = shares.admit(address_in(2, 1), block_of(2), now, true);
  EXPECT_NE(person.id, 0u);
  EXPECT_EQ(person.evicted, address_in(1, 0));
  EXPECT_EQ(shares.open(), 3u);
}

}  // namespace
}  // namespace fw::server
