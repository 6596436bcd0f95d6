// SessionRegistry: the sessions open on the server, apart from its rooms;
// a session counts from its start (before it chose a room) until it ends,
// and a drain tells every one of them to leave.
#include "session_registry.hpp"

#include <gtest/gtest.h>

#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::InMemoryServer;

TEST(SessionRegistry, CountsASessionFromItsStartUntilItEnds) {
  InMemoryServer server;
  SessionRegistry& sessions = server.core().sessions();
  EXPECT_EQ(sessions.count(), 0u);
  auto greeting = server.connect();  // no room chosen yet
  EXPECT_TRUE(eventually([&] { return sessions.count() == 1; }));
  auto ann = server.join("r", "Ann");
  ASSERT_TRUE(ann->welcome);
  EXPECT_TRUE(eventually([&] { return sessions.count() == 2; }));
  greeting.reset();  // hangs up
  EXPECT_TRUE(eventually([&] { return sessions.count() == 1; }));
  EXPECT_EQ(server.core().rooms().list().size(), 1u) << "the rooms are not the sessions";
}

TEST(SessionRegistry, TellsEveryOpenSessionToLeave) {
  InMemoryServer server;
  auto ann = server.join("a", "Ann");
  auto bob = server.join("b", "Bob");
  auto greeting = server.connect();
  ASSERT_TRUE(ann->welcome && bob->welcome);
  EXPECT_TRUE(eventually([&] { return server.core().sessions().count() == 3; }));
  server.core().sessions().close_all();
  for (auto* peer : {ann.get(), bob.get(), greeting.get()}) {
    ASSERT_TRUE(peer->read_until_closed());
    peer->read();
    ASSERT_TRUE(peer->closing);
    EXPECT_EQ(peer->closing->code, CloseCode::shutting_down);
  }
  EXPECT_EQ(server.core().sessions().count(), 0u);
}

}  // namespace
}  // namespace fw::server
