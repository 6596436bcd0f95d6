// RoomRegistry: rooms made on first join up to the room limit, removed when
// their last person leaves (unless persistent), closed for good at the end;
// room names.
#include "room_registry.hpp"

#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "room.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::InMemoryServer;

TEST(RoomNames, AreOneTo64LettersDigitsUnderscoresDashesAndDots) {
  EXPECT_TRUE(is_valid_room_name("lobby"));
  EXPECT_TRUE(is_valid_room_name("Room_2-b.x"));
  EXPECT_TRUE(is_valid_room_name(std::string(codec::kMaxRoomNameBytes, 'a')));
  EXPECT_FALSE(is_valid_room_name(""));
  EXPECT_FALSE(is_valid_room_name(std::string(codec::kMaxRoomNameBytes + 1, 'a')));
  EXPECT_FALSE(is_valid_room_name("two words"));
  EXPECT_FALSE(is_valid_room_name("a/b"));
  EXPECT_FALSE(is_valid_room_name("caf\xc3\xa9"));
}

TEST(RoomRegistry, FindsTheSameRoomByName) {
  InMemoryServer server;
  RoomRegistry& rooms = server.core().rooms();
  const auto a = rooms.find_or_create("a");
  EXPECT_EQ(rooms.find_or_create("a"), a);
  EXPECT_NE(rooms.find_or_create("b"), a);
  EXPECT_EQ(rooms.list().size(), 2u);
  EXPECT_EQ(server.core().metrics().rooms.load(), 2);
}

TEST(RoomRegistry, HoldsAtMostMaxRooms) {
  ServerConfig config = InMemoryServer::test_config();
  config.max_rooms = 2;
  InMemoryServer server(config);
  auto one = server.join("one", "Ann");
  auto two = server.join("two", "Bob");
  auto three = server.join("three", "Cy");
  EXPECT_TRUE(one->welcome && two->welcome);
  ASSERT_TRUE(three->closing);
  EXPECT_EQ(three->closing->code, CloseCode::server_full);
  auto again = server.join("one", "Di");
  EXPECT_TRUE(again->welcome) << "a room that exists takes joiners";
  two.reset();
  EXPECT_TRUE(eventually([&] { return server.core().rooms().list().size() == 1; }));
  auto four = server.join("four", "Ed");
  EXPECT_TRUE(four->welcome) << "an emptied room makes space for another";
}

TEST(RoomRegistry, RemovesOnlyEmptyRoomsThatAreNotPersistent) {
  InMemoryServer server;
  RoomRegistry& rooms = server.core().rooms();
  const auto kept = rooms.find_or_create("kept", /*persistent=*/true);
  const auto gone = rooms.find_or_create("gone");
  rooms.remove_if_empty(kept);
  rooms.remove_if_empty(gone);
  ASSERT_EQ(rooms.list().size(), 1u);
  EXPECT_EQ(rooms.list()[0].name, "kept");
}

TEST(RoomRegistry, OpensNoRoomOnceClosed) {
  InMemoryServer server;
  RoomRegistry& rooms = server.core().rooms();
  rooms.find_or_create("a");
  rooms.close_all_rooms();
  EXPECT_TRUE(rooms.list().empty());
  EXPECT_EQ(rooms.find_or_create("b"), nullptr);
}

}  // namespace
}  // namespace fw::server
