// Who may open one more room, without sockets (RoomShares): shares per
// address and per network block, and the rooms kept for blocks that hold none.
#include <string>

#include <gtest/gtest.h>

#include "room_shares.hpp"

namespace fw::server {
namespace {

TEST(RoomShares, AnAddressAndItsBlockHoldTheirSharesAndNoMore) {
  RoomShares shares({2, 3, 0});
  EXPECT_EQ(shares.may_open("10.0.1.1", "10.0.1.0/24", 0, 100), RoomShareRefusal::none);
  shares.opened("a", "10.0.1.1", "10.0.1.0/24");
  shares.opened("b", "10.0.1.1", "10.0.1.0/24");
  EXPECT_EQ(shares.may_open("10.0.1.1", "10.0.1.0/24", 2, 100), RoomShareRefusal::address);
  EXPECT_EQ(shares.may_open("10.0.1.2", "10.0.1.0/24", 2, 100), RoomShareRefusal::none);
  shares.opened("c", "10.0.1.2", "10.0.1.0/24");
  EXPECT_EQ(shares.may_open("10.0.1.3", "10.0.1.0/24", 3, 100), RoomShareRefusal::block);
  EXPECT_EQ(shares.may_open("10.0.2.1", "10.0.2.0/24", 3, 100), RoomShareRefusal::none) << "another block";
  shares.closed("a");
  EXPECT_EQ(shares.held_by_address("10.0.1.1"), 1u);
  EXPECT_EQ(shares.may_open("10.0.1.3", "10.0.1.0/24", 2, 100), RoomShareRefusal::none) << "a room closed";
  shares.closed("lobby");  // never counted: nothing changes
  EXPECT_EQ(shares.held_by_block("10.0.1.0/24"), 2u);
}

TEST(RoomShares, TheLastRoomsOpenOnlyForBlocksThatHoldNone) {
  RoomShares shares({100, 100, 2});
  for (int i = 0; i < 8; ++i) shares.opened("r" + std::to_string(i), "10.0.1." + std::to_string(i), "10.0.1.0/24");
  EXPECT_EQ(shares.may_open("10.0.1.99", "10.0.1.0/24", 8, 10), RoomShareRefusal::reserve);
  EXPECT_EQ(shares.may_open("10.0.2.1", "10.0.2.0/24", 8, 10), RoomShareRefusal::none);
  shares.opened("fresh", "10.0.2.1", "10.0.2.0/24");
  EXPECT_EQ(shares.may_open("10.0.2.2", "10.0.2.0/24", 9, 10), RoomShareRefusal::reserve)
      << "that block holds one now";
  EXPECT_EQ(shares.may_open("10.0.3.1", "10.0.3.0/24", 9, 10), RoomShareRefusal::none);
  EXPECT_EQ(shares.may_open("10.0.1.99", "10.0.1.0/24", 7, 10), RoomShareRefusal::none) << "below the reserve";
}

}  // namespace
}  // namespace fw::server
