// Every avatar simulates its own face: the room builds it on the worker
// pool, ticking on with the generic face meanwhile, and wears it when it is
// back. Driven through the server core on a real worker pool ticking at 30 Hz.
#include <future>
#include <memory>

#include <gtest/gtest.h>

#include "face_models.hpp"
#include "in_memory_server.hpp"
#include "room.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::eventually;
using test::InMemoryServer;

// Runs `read` on the room's strand and returns its answer; a strand that
// does not answer within 5 s (blocked by a build) fails the test.
template <class Read>
auto on_strand(Room& room, Read read) {
  using Answer = decltype(read(room.simulation()));
  auto answer = std::make_shared<std::promise<Answer>>();
  auto future = answer->get_future();
  room.then([answer, read, &room] { answer->set_value(read(room.simulation())); });
  if (future.wait_for(5s) != std::future_status::ready) {
    ADD_FAILURE() << "the room's strand did not answer in 5 s";
    return Answer{};
  }
  return future.get();
}

ServerConfig two_workers() {
  ServerConfig config = InMemoryServer::test_config(2);
  config.workers = 2;  // one held by the build below, one ticking
  return config;
}

TEST(RoomOwnFaces, TheRoomTicksWhileAnAvatarsFaceIsBuiltAndWearsItWhenBack) {
  InMemoryServer server(two_workers());
  const StoredAvatar face = server.core().demo_avatars().at(1);
  ASSERT_EQ(server.core().face_models().find(face.version), nullptr);
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<int> building{0};
  server.core().face_models().set_before_build([&building, released] {
    building.fetch_add(1);
    released.wait();
  });
  auto room = server.core().rooms().find_or_create("own-faces", /*persistent=*/true);
  JoinRequest request;
  request.name = "Auto";
  request.avatar = face;
  room->join(std::move(request));
  const auto ids = on_strand(*room, [](RoomSimulation& s) { return s.avatars(); });
  ASSERT_EQ(ids.size(), 1u);
  const std::uint32_t id = ids[0];
  ASSERT_TRUE(eventually([&] { return building.load() == 1; }, 5s));
  // The build is held: the room ticks on, the avatar on the generic face.
  const auto tick = on_strand(*room, [](RoomSimulation& s) { return s.tick_index(); });
  ASSERT_TRUE(eventually([&] { return on_strand(*room, [](RoomSimulation& s) { return s.tick_index(); }) >= tick + 10; },
                         10s))
      << "the room stopped ticking while a face was built";
  EXPECT_FALSE(on_strand(*room, [id](RoomSimulation& s) { return s.wears_own_face(id); }));
  release.set_value();
  EXPECT_TRUE(eventually([&] { return on_strand(*room, [id](RoomSimulation& s) { return s.wears_own_face(id); }); }, 10s));
  EXPECT_EQ(server.core().face_models().builds(), 1u);
}

TEST(RoomOwnFaces, OnePackageIsBuiltOnceForEveryRoomThatSeatsIt) {
  InMemoryServer server(two_workers());
  const StoredAvatar face = server.core().demo_avatars().at(0);
  std::vector<std::shared_ptr<Room>> rooms;
  for (const char* name : {"first", "second"}) {
    auto room = server.core().rooms().find_or_create(name, /*persistent=*/true);
    JoinRequest request;
    request.name = "Auto";
    request.avatar = face;
    room->join(std::move(request));
    // The first room's face is worn before the second room asks.
    ASSERT_TRUE(eventually(
        [&] {
          return on_strand(*room, [](RoomSimulation& s) { return !s.avatars().empty() && s.wears_own_face(s.avatars()[0]); });
        },
        10s));
    rooms.push_back(room);
  }
  EXPECT_EQ(server.core().face_models().builds(), 1u);
  EXPECT_TRUE(server.core().face_models().find(face.version));
}

}  // namespace
}  // namespace fw::server
