// The in-memory transport itself: what the peer pushes reaches the session,
// what the session writes reaches the peer, and a peer that stops reading
// leaves the session's queue growing until it reads again.
#include "in_memory_session.hpp"

#include <gtest/gtest.h>

#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using test::eventually;
using test::InMemoryServer;
using namespace std::chrono_literals;

SharedBytes bytes_of(std::size_t size, std::uint8_t fill) {
  return share(std::vector<std::uint8_t>(size, fill));
}

TEST(InMemorySession, WritesWhatIsDeliveredInOrderWithItsFraming) {
  InMemoryServer server;
  auto peer = server.connect();
  InMemorySession& session = peer->session();
  session.deliver(bytes_of(100, 1));
  session.deliver(bytes_of(200, 2));
  std::vector<SharedBytes> written;
  ASSERT_TRUE(eventually([&] {
    for (auto& message : session.take_written()) written.push_back(std::move(message));
    return written.size() == 2;
  }));
  EXPECT_EQ(written[0]->front(), 1);
  EXPECT_EQ(written[1]->size(), 200u);
  EXPECT_EQ(session.framing_bytes(100), 1u);
  EXPECT_EQ(session.framing_bytes(200), 2u);
  EXPECT_TRUE(eventually([&] { return session.bytes_written() == 100 + 1 + 200 + 2; }));
  EXPECT_EQ(session.queued_bytes(), 0u);
}

TEST(InMemorySession, APeerThatDoesNotReadLeavesEverythingQueuedUntilItReads) {
  InMemoryServer server;
  auto peer = server.connect();
  InMemorySession& session = peer->session();
  session.set_reading(false);
  for (int i = 0; i < 10; ++i) session.deliver(bytes_of(1000, static_cast<std::uint8_t>(i)));
  std::this_thread::sleep_for(50ms);
  EXPECT_EQ(session.queued_bytes(), 10'000u) << "nothing leaves while the peer does not read";
  EXPECT_EQ(session.bytes_written(), 0u);
  EXPECT_TRUE(session.take_written().empty());

  session.set_reading(true);
  EXPECT_TRUE(eventually([&] { return session.queued_bytes() == 0; }));
  const auto written = session.take_written();
  ASSERT_EQ(written.size(), 10u);
  for (std::size_t i = 0; i < written.size(); ++i) EXPECT_EQ(written[i]->front(), i);
}

TEST(InMemorySession, PushedMessagesReachTheSessionAsIfReadFromASocket) {
  InMemoryServer server;
  auto peer = server.join("r", "Ann");
  ASSERT_TRUE(peer->welcome) << (peer->closing ? peer->closing->reason : "no answer");
  const auto received = server.core().metrics().bytes_received.load();
  EXPECT_GT(received, 0u) << "the hello counts as received";
  peer->send(codec::Ping{42, 7});
  ASSERT_TRUE(peer->read_until([&] { return !peer->pongs.empty(); }));
  EXPECT_EQ(peer->pongs[0].nonce, 42u);
  EXPECT_EQ(peer->pongs[0].client_time_us, 7u);
}

TEST(InMemorySession, HangingUpLeavesTheRoomAndTheRegistry) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  EXPECT_EQ(server.core().sessions().count(), 2u);
  bob->session().hang_up();
  EXPECT_TRUE(eventually([&] { return bob->session().gone(); }));
  ASSERT_TRUE(ann->read_until([&] { return ann->presence.size() >= 2; }));
  EXPECT_EQ(ann->presence.back().change, codec::Presence::Change::left);
  EXPECT_EQ(server.core().sessions().count(), 1u);
  EXPECT_FALSE(bob->session().shut_down()) << "the peer ended it, not the server";
}

TEST(InMemorySession, AServerCloseWritesTheClosingMessageThenEndsThePipe) {
  InMemoryServer server;
  auto peer = server.connect();
  peer->session().close(codec::CloseCode::normal, "bye");
  ASSERT_TRUE(peer->read_until_closed());
  peer->read();
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->reason, "bye");
  EXPECT_EQ(peer->session().shut_down(), codec::CloseCode::normal);
  EXPECT_FALSE(peer->session().aborted());
}

}  // namespace
}  // namespace fw::server
