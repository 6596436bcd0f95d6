// The avatar store on real files in a temporary directory: photos kept
// beside packages, ids that never change hands, crashes mid-write, and
// stored avatars of another package format or generic face refused with what
// to do when they cannot be prepared again (no photo, or a server without a
// photo worker) or are corrupt. Preparing them again from their photo is in
// avatar_repreparation_test.cpp.
#include "avatar_store.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "demo_faces.hpp"
#include "fw/model/avatar_package.hpp"
#include "file_bytes.hpp"
#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::file_bytes;
using test::write_file_bytes;
using test::InMemoryServer;

/// A real package, as an older build made it: fitted to the previous generic face.
std::vector<std::uint8_t> package_of_an_older_generic_face() {
  model::AvatarPackage package;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(make_demo_package(0), package, error)) << error;
  package.generic_face_version -= 1;
  return model::serialize_avatar_package(package);
}

/// A data directory of its own, removed at the end.
class StoreDirectory : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directories(avatars_); }
  void TearDown() override { std::filesystem::remove_all(data_); }

  std::filesystem::path file(const std::string& asset, const std::string& suffix) const {
    return avatars_ / (asset + suffix);
  }
  /// A hello that wears `asset`, on a server started on this directory.
  std::unique_ptr<test::InMemoryPeer> join_wearing(InMemoryServer& server, const std::string& asset) {
    test::HelloOptions options;
    options.avatar = asset;
    return server.join("r", "Ann", options);
  }
  /// The reason a hello wearing asset_ is refused for good (closing 10, bad request).
  std::string refused_hello(InMemoryServer& server) {
    const auto peer = join_wearing(server, asset_);
    if (!peer->closing) {
      ADD_FAILURE() << "the hello was not refused";
      return {};
    }
    EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
    return peer->closing->reason;
  }

  const std::filesystem::path data_ = std::filesystem::temp_directory_path() /
                                      ("fw-store-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const std::filesystem::path avatars_ = data_ / "avatars";
  const std::string asset_ = "0123456789abcdef0123456789abcdef";
  Metrics metrics_;
};

TEST_F(StoreDirectory, KeepsThePhotoBesideThePackage) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const auto package = make_demo_package(0);
  const std::vector<std::uint8_t> photo = {0xFF, 0xD8, 0xFF, 1, 2, 3};
  const auto stored = store.put(package, photo, error);
  ASSERT_TRUE(stored) << error;
  EXPECT_EQ(file_bytes(file(stored->asset, ".photo")), photo);
  EXPECT_EQ(file_bytes(file(stored->asset, ".fwa")), package);
  EXPECT_EQ(stored->version, stored->asset) << "first stored: the id is the package's hash";
}

TEST_F(StoreDirectory, AnUploadNeverChangesAStoredAvatar) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const auto package = make_demo_package(0);
  const std::vector<std::uint8_t> first_photo = {1, 1, 1}, other_photo = {2, 2, 2};
  const auto first = store.put(package, error);
  ASSERT_TRUE(first) << error;
  EXPECT_FALSE(std::filesystem::exists(file(first->asset, ".photo")));
  // Someone who downloaded the package sends it again with a photo of their
  // own: were it kept, the avatar would become their face when prepared again.
  const auto again = store.put(package, other_photo, error);
  ASSERT_TRUE(again) << error;
  EXPECT_EQ(again->asset, first->asset);
  EXPECT_FALSE(std::filesystem::exists(file(first->asset, ".photo")));

  const auto second_package = make_demo_package(1);
  const auto second = store.put(second_package, first_photo, error);
  ASSERT_TRUE(second) << error;
  store.put(second_package, other_photo, error);
  EXPECT_EQ(file_bytes(file(second->asset, ".photo")), first_photo);
}

TEST_F(StoreDirectory, ACrashMidWriteLosesNothing) {
  const auto package = make_demo_package(0);
  const std::vector<std::uint8_t> photo = {0xFF, 0xD8, 0xFF, 7};
  std::string asset;
  {
    std::string error;
    AvatarStore store(data_, metrics_, error);
    const auto stored = store.put(package, photo, error);
    ASSERT_TRUE(stored) << error;
    asset = stored->asset;
  }
  // Killed while writing the package again (its temporary file is left
  // half-written beside it), and before the preview was written.
  write_file_bytes(file(asset, ".fwa.partial-4242"), std::span(package).first(100));
  std::filesystem::remove(file(asset, ".preview.fwa"));

  std::string error;
  AvatarStore reopened(data_, metrics_, error);
  const AvatarLookup found = reopened.lookup(asset);
  ASSERT_EQ(found.status, AvatarStatus::found) << found.message;
  EXPECT_EQ(*found.avatar->full, package);
  model::AvatarPackage preview;
  EXPECT_TRUE(model::parse_avatar_package(*found.avatar->preview, preview, error)) << error;
  EXPECT_EQ(file_bytes(file(asset, ".preview.fwa")), *found.avatar->preview) << "the preview is made again";
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo);
}

TEST_F(StoreDirectory, AnOutOfDateAvatarWithoutItsPhotoIsRefusedWithTheAdviceToUploadAgain) {
  write_file_bytes(file(asset_, ".fwa"), package_of_an_older_generic_face());
  InMemoryServer server(InMemoryServer::test_config(), data_);
  const std::string reason = refused_hello(server);
  EXPECT_NE(reason.find("upload your photo again"), std::string::npos) << reason;
  EXPECT_EQ(server.context().metrics.outdated_avatars.load(), 1u);
  EXPECT_EQ(server.context().metrics.repreparations_started.load(), 0u);
  EXPECT_EQ(refused_hello(server), reason) << "the same answer again";
  EXPECT_EQ(server.context().metrics.outdated_avatars.load(), 1u) << "counted once";
}

TEST_F(StoreDirectory, AnOutOfDateAvatarIsRefusedWhereNobodyCanPrepareItAgain) {
  // A server core without a photo worker (no repreparer): the photo is kept
  // for a server that has one, and the person is told what to do meanwhile.
  write_file_bytes(file(asset_, ".fwa"), package_of_an_older_generic_face());
  write_file_bytes(file(asset_, ".photo"), std::vector<std::uint8_t>{0xFF, 0xD8, 0xFF});
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const AvatarLookup refused = store.lookup(asset_);
  EXPECT_EQ(refused.status, AvatarStatus::out_of_date);
  EXPECT_NE(refused.message.find("upload your photo again"), std::string::npos) << refused.message;
  EXPECT_TRUE(std::filesystem::exists(file(asset_, ".photo")));
}

TEST_F(StoreDirectory, ACorruptPackageIsRefusedAsCorrupt) {
  auto package = make_demo_package(0);
  package[package.size() - 3] ^= 0x10;  // inside the last member: its checksum fails
  write_file_bytes(file(asset_, ".fwa"), package);
  write_file_bytes(file(asset_, ".photo"), std::vector<std::uint8_t>{0xFF, 0xD8, 0xFF});
  InMemoryServer server(InMemoryServer::test_config(), data_);
  const std::string reason = refused_hello(server);
  EXPECT_NE(reason.find("damaged"), std::string::npos) << reason;
  EXPECT_EQ(server.context().metrics.damaged_avatars.load(), 1u);
  EXPECT_EQ(server.context().metrics.repreparations_started.load(), 0u) << "damage is not an old version";
}

TEST_F(StoreDirectory, TheSamePackageRepairsADamagedOne) {
  const auto package = make_demo_package(0);
  std::string error;
  std::string asset;
  {
    AvatarStore store(data_, metrics_, error);
    asset = store.put(package, error)->asset;
  }
  auto damaged = package;
  damaged[damaged.size() / 2] ^= 1;
  write_file_bytes(file(asset, ".fwa"), damaged);
  AvatarStore store(data_, metrics_, error);
  EXPECT_EQ(store.lookup(asset).status, AvatarStatus::damaged);
  const auto repaired = store.put(package, error);
  ASSERT_TRUE(repaired) << error;
  EXPECT_EQ(repaired->asset, asset);
  EXPECT_EQ(store.lookup(asset).status, AvatarStatus::found);
  EXPECT_EQ(file_bytes(file(asset, ".fwa")), package);
}

}  // namespace
}  // namespace fw::server
