// ServerCore, a server without its sockets: the avatar store and demo faces
// it opens, the lobby and readiness, a drain, and a stop.
#include "server_core.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::InMemoryServer;

TEST(ServerCore, OpensTheStoreWithTheDemoFaces) {
  InMemoryServer server(InMemoryServer::test_config(2));
  const auto& demo = server.core().demo_avatars();
  ASSERT_EQ(demo.size(), 2u);
  EXPECT_NE(demo[0].asset, demo[1].asset) << "every face its own";
  for (const StoredAvatar& face : demo) {
    EXPECT_TRUE(is_asset_id(face.asset));
    ASSERT_TRUE(face.preview && face.full);
    EXPECT_LT(face.preview->size(), face.full->size());
    EXPECT_TRUE(server.core().store().get(face.asset)) << "stored like an upload";
  }
  EXPECT_TRUE(server.core().state().ready.load()) << "no demo room: ready at once";
}

TEST(ServerCore, IsWholeWhenMadeAndUsableAtOnce) {
  ServerConfig config = InMemoryServer::test_config(2);
  config.data = (std::filesystem::temp_directory_path() / ("fw-whole-" + std::to_string(::getpid()))).string();
  std::string error;
  auto core = ServerCore::open(config, error);
  ASSERT_NE(core, nullptr) << error;
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(core->demo_avatars().size(), 2u);
  EXPECT_TRUE(is_asset_id(core->demo_avatars()[0].asset));
  EXPECT_FALSE(core->server_key().empty());
  // What sessions are made with is the core's own, not copies filled in apart.
  const SessionServices& sessions = core->session_services();
  EXPECT_EQ(&sessions.store, &core->store());
  EXPECT_EQ(&sessions.rooms, &core->rooms());
  EXPECT_EQ(&sessions.sessions, &core->sessions());
  EXPECT_EQ(&sessions.procedural_faces, &core->demo_avatars());
  EXPECT_EQ(&sessions.server_key, &core->server_key());
  EXPECT_EQ(&sessions.draining, &core->state().draining);
  // No open() to complete it: a room opens, ticks on the pool and is counted.
  EXPECT_NE(core->rooms().find_or_create("r"), nullptr);
  EXPECT_EQ(core->metrics().rooms.load(), 1);
  EXPECT_TRUE(core->store().get(core->demo_avatars()[1].asset));
  core->stop();
  EXPECT_TRUE(core->rooms().list().empty());

  // Made again on the same directory (a restart): the same key, the same faces.
  const std::string key = core->server_key();
  const std::string face = core->demo_avatars()[0].asset;
  core.reset();
  const auto again = ServerCore::open(config, error);
  ASSERT_NE(again, nullptr) << error;
  EXPECT_EQ(again->server_key(), key);
  EXPECT_EQ(again->demo_avatars()[0].asset, face);
  again->stop();
  std::filesystem::remove_all(config.data);
}

TEST(ServerCore, SaysWhyItCannotOpenTheStore) {
  const auto file = std::filesystem::temp_directory_path() / ("fw-not-a-dir-" + std::to_string(::getpid()));
  std::ofstream(file) << "x";
  ServerConfig config = InMemoryServer::test_config();
  config.data = file.string();
  std::string error;
  EXPECT_EQ(ServerCore::open(config, error), nullptr) << "no half-made core";
  EXPECT_NE(error.find("cannot create the avatar store"), std::string::npos) << error;
  EXPECT_NE(error.find("--data DIR"), std::string::npos) << error;
  std::filesystem::remove(file);
}

TEST(ServerCore, AClientWithoutAPackageNeedsADemoFace) {
  ServerConfig config = InMemoryServer::test_config();
  config.demo_room = true;
  config.demo_faces = 0;
  config.data = (std::filesystem::temp_directory_path() / ("fw-lobby-" + std::to_string(::getpid()))).string();
  std::string error;
  EXPECT_EQ(ServerCore::open(config, error), nullptr);
  EXPECT_NE(error.find("at least 1"), std::string::npos) << error;
  std::filesystem::remove_all(config.data);
}

TEST(ServerCore, StoresTheResidentsFacesApartFromTheDemoFaces) {
  InMemoryServer server(InMemoryServer::test_config(1));
  const auto& residents = server.core().residents();
  ASSERT_EQ(residents.size(), 3u);
  for (const StoredAvatar& face : residents) {
    EXPECT_TRUE(server.core().store().get(face.asset)) << "stored like an upload";
    EXPECT_NE(face.asset, server.core().demo_avatars()[0].asset)
        << "a client without a package is never given a resident's face";
  }
  EXPECT_EQ(server.core().own_faces().size(), 4u) << "the server's own: nobody's to delete";
}

TEST(ServerCore, IsReadyOnceTheLobbyIsSeated) {
  ServerConfig config = InMemoryServer::test_config(1);
  config.demo_room = true;
  InMemoryServer server(config);
  EXPECT_TRUE(eventually([&] { return server.core().state().ready.load(); }));
  const auto rooms = server.core().rooms().list();
  ASSERT_EQ(rooms.size(), 1u);
  EXPECT_EQ(rooms[0].name, "lobby");
  EXPECT_EQ(rooms[0].avatars, 3u);
  EXPECT_EQ(rooms[0].persons, 0u);
  auto visitor = server.join("lobby", "Visitor");
  ASSERT_TRUE(visitor->welcome);
  EXPECT_EQ(visitor->welcome->avatars[0].name, "Ada") << "she leads";
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(visitor->welcome->avatars[i].asset, server.core().residents()[i].asset) << "each in her or his own face";
}

TEST(ServerCore, ADrainTellsEveryoneAndRefusesNewcomers) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  ASSERT_TRUE(ann->welcome);
  EXPECT_FALSE(server.core().drained());
  server.core().start_draining();
  ASSERT_TRUE(ann->read_until_closed());
  ann->read();
  ASSERT_TRUE(ann->closing);
  EXPECT_EQ(ann->closing->code, CloseCode::shutting_down);
  EXPECT_TRUE(eventually([&] { return server.core().drained(); }));
  auto late = server.join("r", "Late");
  ASSERT_TRUE(late->closing);
  EXPECT_EQ(late->closing->code, CloseCode::shutting_down);
}

TEST(ServerCore, StopsItsRoomsAndWorkers) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  ASSERT_TRUE(ann->welcome);
  ann.reset();
  server.core().stop();
  EXPECT_TRUE(server.core().rooms().list().empty());
  EXPECT_EQ(server.core().rooms().find_or_create("later"), nullptr);
}

}  // namespace
}  // namespace fw::server
