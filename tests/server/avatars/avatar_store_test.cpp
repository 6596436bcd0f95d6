// The avatar store on real files in a temporary directory: photos kept
// beside packages, ids that never change hands (every upload a new one),
// avatars deleted by their uploader, the keys that open them, crashes
// mid-write, and
// stored avatars of another package format or generic face refused with what
// to do when they cannot be prepared again (no photo, or a server without a
// photo worker) or are corrupt. Preparing them again from their photo is in
// avatar_repreparation_test.cpp.
#include "avatar_store.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "avatar_deletion.hpp"
#include "avatar_retention.hpp"
#include "demo_faces.hpp"
#include "room_members.hpp"
#include "fw/model/avatar_package.hpp"
#include "file_bytes.hpp"
#include "in_memory_server.hpp"
#include "server_keys.hpp"

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
  EXPECT_NE(stored->version, stored->asset) << "the id is random, not the package's hash";
}

TEST_F(StoreDirectory, AnUploadNeverChangesAStoredAvatarAndTheSameBytesMakeAnotherOne) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const auto package = make_demo_package(0);
  const std::vector<std::uint8_t> other_photo = {2, 2, 2};
  const auto first = store.put(package, error);
  ASSERT_TRUE(first) << error;
  EXPECT_FALSE(std::filesystem::exists(file(first->asset, ".photo")));
  // Someone who downloaded the package sends it again with a photo of their
  // own: another avatar, under another id; the first keeps its bytes.
  const auto again = store.put(package, other_photo, error);
  ASSERT_TRUE(again) << error;
  EXPECT_NE(again->asset, first->asset);
  EXPECT_TRUE(is_asset_id(again->asset));
  EXPECT_EQ(again->version, first->version) << "the same bytes";
  EXPECT_FALSE(std::filesystem::exists(file(first->asset, ".photo")));
  EXPECT_EQ(file_bytes(file(again->asset, ".photo")), other_photo);
  EXPECT_EQ(file_bytes(file(first->asset, ".fwa")), package);
}

TEST_F(StoreDirectory, TheServersOwnFacesAreFoundAgainUnderTheirHash) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const auto package = make_demo_package(0);
  const auto first = store.put_own_face(package, error);
  ASSERT_TRUE(first) << error;
  EXPECT_EQ(first->asset, first->version);
  const auto again = store.put_own_face(package, error);
  ASSERT_TRUE(again) << error;
  EXPECT_EQ(again->asset, first->asset);
  EXPECT_EQ(store.stored_assets().size(), 1u);
}

TEST_F(StoreDirectory, ADeletedAvatarIsGoneWithItsPhotoAndStaysGone) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const auto package = make_demo_package(0);
  const std::vector<std::uint8_t> photo = {0xFF, 0xD8, 0xFF, 5};
  const auto stored = store.put(package, photo, error);
  ASSERT_TRUE(stored) << error;
  const auto kept = store.put(package, error);  // a copy: another avatar, untouched
  ASSERT_TRUE(kept) << error;
  EXPECT_TRUE(store.remove(stored->asset));
  EXPECT_EQ(metrics_.deleted_avatars.load(), 1u);
  for (const char* suffix : {".fwa", ".preview.fwa", ".photo"})
    EXPECT_FALSE(std::filesystem::exists(file(stored->asset, suffix))) << suffix;
  const AvatarLookup gone = store.lookup(stored->asset);
  EXPECT_EQ(gone.status, AvatarStatus::deleted);
  EXPECT_NE(gone.message.find("deleted"), std::string::npos) << gone.message;
  EXPECT_FALSE(store.remove(stored->asset)) << "nothing left to delete";
  EXPECT_EQ(store.lookup(kept->asset).status, AvatarStatus::found);

  // A preparation that was running when it was deleted does not bring it back.
  EXPECT_FALSE(store.replace(stored->asset, package, error));
  EXPECT_FALSE(std::filesystem::exists(file(stored->asset, ".fwa")));
  EXPECT_EQ(store.lookup(stored->asset).status, AvatarStatus::deleted);
  EXPECT_EQ(metrics_.repreparation_failures.load(), 0u) << "not a failure: it is gone, as asked";

  // After a restart it is unknown: nothing of it is left to find.
  AvatarStore reopened(data_, metrics_, error);
  EXPECT_EQ(reopened.lookup(stored->asset).status, AvatarStatus::unknown);
  EXPECT_EQ(reopened.lookup(kept->asset).status, AvatarStatus::found);
}

TEST_F(StoreDirectory, AvatarsUnusedForTheRetentionPeriodAreSweptWithTheirPhotos) {
  std::string error;
  AvatarStore store(data_, metrics_, error);
  const std::vector<std::uint8_t> photo = {0xFF, 0xD8, 0xFF, 9};
  const auto stale = store.put(make_demo_package(0), photo, error);
  const auto fresh = store.put(make_demo_package(1), photo, error);
  const auto own = store.put_own_face(make_demo_package(2), error);
  ASSERT_TRUE(stale && fresh && own) << error;
  const auto now = std::filesystem::file_time_type::clock::now();
  const AvatarRetention thirty_days(30);
  // Last used 31 days ago (the package file's time is its last use).
  for (const auto& asset : {stale->asset, own->asset})
    std::filesystem::last_write_time(file(asset, ".fwa"), now - std::chrono::hours(24 * 31));
  const auto removed = store.remove_unused_since(*thirty_days.cutoff(now), {own->asset});
  ASSERT_EQ(removed, std::vector<std::string>{stale->asset});
  EXPECT_EQ(metrics_.expired_avatars.load(), 1u);
  EXPECT_FALSE(std::filesystem::exists(file(stale->asset, ".photo")));
  EXPECT_FALSE(std::filesystem::exists(file(stale->asset, ".fwa")));
  EXPECT_EQ(store.lookup(stale->asset).status, AvatarStatus::unknown);
  EXPECT_EQ(store.lookup(fresh->asset).status, AvatarStatus::found);
  EXPECT_EQ(store.lookup(own->asset).status, AvatarStatus::found) << "the server's own faces stay";

  // A use moves the last use to now: a worn avatar is not swept.
  EXPECT_GT(std::filesystem::last_write_time(file(own->asset, ".fwa")), now - std::chrono::hours(1));
  EXPECT_FALSE(AvatarRetention(0).cutoff(now)) << "0: kept until deleted";
  EXPECT_EQ(*AvatarRetention(1).cutoff(now), now - std::chrono::hours(24));
}

TEST(AvatarKeys, IdsAreRandomAndEachKeyOpensItsOwnAvatarOnly) {
  const std::string server_key(32, 'k'), other_server(32, 'o');
  const std::string a = new_asset_id(), b = new_asset_id();
  EXPECT_TRUE(is_asset_id(a)) << a;
  EXPECT_TRUE(is_asset_id(b)) << b;
  EXPECT_NE(a, b);
  const std::string key_a = avatar_key(server_key, a);
  EXPECT_EQ(key_a.size(), 22u);
  EXPECT_EQ(avatar_key(server_key, a), key_a) << "the same on every node and after a restart";
  EXPECT_TRUE(avatar_key_matches(server_key, a, key_a));
  EXPECT_FALSE(avatar_key_matches(server_key, b, key_a));
  EXPECT_FALSE(avatar_key_matches(other_server, a, key_a)) << "the server key signs it";
  EXPECT_FALSE(avatar_key_matches(server_key, a, key_a.substr(1)));
  EXPECT_FALSE(avatar_key_matches(server_key, a, ""));
  // An id from before ids were random (a package's hash) keeps the key it was given.
  const std::string legacy = "00112233445566778899aabbccddeeff";
  EXPECT_TRUE(avatar_key_matches(server_key, legacy, avatar_key(server_key, legacy)));
}

/// What a deletion on `core` decides with, as the REST API makes it.
AvatarDeletionServices deletion_in(ServerCore& core) {
  return {core.store(), core.rooms(), core.demo_avatars(), core.server_key()};
}

TEST(AvatarDeletionDecision, OnlyTheRightKeyDeletesAndNeverTheServersFaces) {
  InMemoryServer server;
  ServerCore& core = server.core();
  const AvatarDeletionServices deletion = deletion_in(core);
  std::string error;
  const auto stored = core.store().put(make_demo_package(4), error);
  ASSERT_TRUE(stored) << error;
  const std::string key = avatar_key(core.server_key(), stored->asset);
  const std::string face = core.demo_avatars().at(0).asset;
  EXPECT_EQ(delete_avatar(deletion, face, avatar_key(core.server_key(), face)), AvatarDeletion::server_face);
  EXPECT_EQ(delete_avatar(deletion, stored->asset, ""), AvatarDeletion::no_key);
  EXPECT_EQ(delete_avatar(deletion, stored->asset, avatar_key(core.server_key(), face)), AvatarDeletion::wrong_key);
  EXPECT_EQ(core.store().lookup(stored->asset).status, AvatarStatus::found);
  EXPECT_EQ(delete_avatar(deletion, "not-an-id", key), AvatarDeletion::unknown);
  EXPECT_EQ(delete_avatar(deletion, stored->asset, key), AvatarDeletion::deleted);
  EXPECT_EQ(delete_avatar(deletion, stored->asset, key), AvatarDeletion::unknown);
  EXPECT_EQ(core.store().lookup(face).status, AvatarStatus::found);
  for (const auto outcome : {AvatarDeletion::unknown, AvatarDeletion::no_key, AvatarDeletion::wrong_key,
                             AvatarDeletion::server_face})
    EXPECT_FALSE(deletion_message(outcome, stored->asset).empty());
}

TEST(AvatarDeletionDecision, WhoWoreADeletedAvatarIsShownWithTheProceduralFaceOfTheirName) {
  InMemoryServer server(InMemoryServer::test_config(3));
  ServerCore& core = server.core();
  std::string error;
  const auto stored = core.store().put(make_demo_package(5), error);
  ASSERT_TRUE(stored) << error;
  test::HelloOptions wearing;
  wearing.avatar = stored->asset;
  auto ann = server.join("r", "Ann", wearing);
  ASSERT_TRUE(ann->welcome);
  auto bo = server.join("r", "Bo");
  ASSERT_TRUE(bo->welcome);
  const std::uint32_t ann_id = ann->welcome->you;
  const auto full = std::make_pair(ann_id, static_cast<int>(codec::PackageChunk::Quality::full));
  ASSERT_TRUE(bo->read_until([&] { return bo->packages[full].complete(); }));
  EXPECT_EQ(bo->packages[full].bytes, *stored->full);

  EXPECT_EQ(delete_avatar(deletion_in(core), stored->asset, avatar_key(core.server_key(), stored->asset)),
            AvatarDeletion::deleted);
  const StoredAvatar& procedural = procedural_face_for(core.demo_avatars(), "Ann");
  EXPECT_TRUE(bo->read_until([&] { return bo->packages[full].complete() && bo->packages[full].bytes == *procedural.full; }))
      << "Bo still sees the deleted face";
  EXPECT_TRUE(bo->errors.empty()) << bo->errors.front();
  // A newcomer is told the face she wears now.
  auto cy = server.join("r", "Cy");
  ASSERT_TRUE(cy->welcome);
  bool told = false;
  for (const auto& info : cy->welcome->avatars) {
    if (info.id != ann_id) continue;
    told = true;
    EXPECT_EQ(info.asset, procedural.asset);
  }
  EXPECT_TRUE(told) << "Ann is still in the room";
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
  EXPECT_EQ(server.core().metrics().outdated_avatars.load(), 1u);
  EXPECT_EQ(server.core().metrics().repreparations_started.load(), 0u);
  EXPECT_EQ(refused_hello(server), reason) << "the same answer again";
  EXPECT_EQ(server.core().metrics().outdated_avatars.load(), 1u) << "counted once";
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
  EXPECT_EQ(server.core().metrics().damaged_avatars.load(), 1u);
  EXPECT_EQ(server.core().metrics().repreparations_started.load(), 0u) << "damage is not an old version";
}

TEST_F(StoreDirectory, TheSameFaceOfTheServersOwnRepairsADamagedOne) {
  const auto package = make_demo_package(0);
  std::string error;
  std::string asset;
  {
    AvatarStore store(data_, metrics_, error);
    asset = store.put_own_face(package, error)->asset;
  }
  auto damaged = package;
  damaged[damaged.size() / 2] ^= 1;
  write_file_bytes(file(asset, ".fwa"), damaged);
  AvatarStore store(data_, metrics_, error);
  EXPECT_EQ(store.lookup(asset).status, AvatarStatus::damaged);
  const auto repaired = store.put_own_face(package, error);
  ASSERT_TRUE(repaired) << error;
  EXPECT_EQ(repaired->asset, asset);
  EXPECT_EQ(store.lookup(asset).status, AvatarStatus::found);
  EXPECT_EQ(file_bytes(file(asset, ".fwa")), package);
  // An upload of the same bytes is someone's avatar of their own, never a repair.
  const auto uploaded = store.put(package, error);
  ASSERT_TRUE(uploaded) << error;
  EXPECT_NE(uploaded->asset, asset);
}

}  // namespace
}  // namespace fw::server
