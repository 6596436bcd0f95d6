// Stored avatars of an older generic face prepared again from the photo kept
// beside them, with the real preparer on the astronaut portrait, through the
// server core and in-memory connections: a restarted server serves the
// avatar again under the same id, and a join meanwhile gets the temporary
// answer; a photo that no longer makes an avatar is refused. One process
// (the landmark model loads once, on the photo worker the tests share). The
// same over HTTP, with uploads: room_server_test.cpp.
#include "avatar_repreparation.hpp"

#include <filesystem>
#include <future>

#include <gtest/gtest.h>

#include "demo_faces.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "file_bytes.hpp"
#include "in_memory_server.hpp"
#include "photo_worker.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using codec::CloseCode;
using test::file_bytes;
using test::InMemoryServer;

class Repreparation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { worker_ = new PhotoWorker(""); }
  static void TearDownTestSuite() {
    delete worker_;
    worker_ = nullptr;
  }
  void TearDown() override { std::filesystem::remove_all(data_); }

  std::filesystem::path file(const std::string& asset, const std::string& suffix) const {
    return data_ / "avatars" / (asset + suffix);
  }

  /// `photo` prepared on the worker and stored with it, as an upload does.
  static std::string upload(AvatarStore& store, const std::vector<std::uint8_t>& photo) {
    std::promise<std::string> asset;
    worker_->post([&] {
      photo::PrepError prep_error;
      photo::AvatarPreparer* preparer = worker_->preparer(prep_error);
      const auto prepared = preparer ? preparer->prepare(photo, photo::PrepOptions{}, prep_error) : std::nullopt;
      EXPECT_TRUE(prepared) << prep_error.message;
      std::string error;
      const auto stored = prepared ? store.put(model::serialize_avatar_package(prepared->package), photo, error)
                                   : std::nullopt;
      EXPECT_TRUE(stored) << error;
      asset.set_value(stored ? stored->asset : "");
    });
    return asset.get_future().get();
  }

  /// What a build with the previous generic face stored: `package`, fitted to it.
  void store_out_of_date(const std::string& asset, const std::vector<std::uint8_t>& package) const {
    model::AvatarPackage parsed;
    std::string error;
    ASSERT_TRUE(model::parse_avatar_package(package, parsed, error)) << error;
    parsed.generic_face_version -= 1;
    std::filesystem::create_directories(data_ / "avatars");
    ASSERT_TRUE(model::write_file_atomically(file(asset, ".fwa"), model::serialize_avatar_package(parsed), error))
        << error;
  }

  static std::unique_ptr<test::InMemoryPeer> join_wearing(InMemoryServer& server, const std::string& asset) {
    test::HelloOptions options;
    options.avatar = asset;
    return server.join("r", "Ann", options);
  }

  static inline PhotoWorker* worker_ = nullptr;
  const std::filesystem::path data_ = std::filesystem::temp_directory_path() /
                                      ("fw-reprep-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
};

TEST_F(Repreparation, AnOutOfDateAvatarIsServedAgainUnderTheSameIdAfterARestart) {
  const auto photo = file_bytes(test::test_photo("astronaut.png"));
  std::string asset;
  {
    InMemoryServer server(InMemoryServer::test_config(), data_);
    asset = upload(server.core().store(), photo);
    ASSERT_FALSE(asset.empty());
  }
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo) << "the photo as uploaded, beside its package";

  // The server is upgraded to a new generic face; it had crashed once while
  // writing this package (its temporary file is still there).
  store_out_of_date(asset, file_bytes(file(asset, ".fwa")));
  const auto older = file_bytes(file(asset, ".fwa"));
  std::filesystem::copy_file(file(asset, ".fwa"), file(asset, ".fwa.partial-4242"));

  InMemoryServer server(InMemoryServer::test_config(), data_);
  AvatarRepreparation repreparation(server.core().store(), *worker_);
  const auto early = join_wearing(server, asset);
  ASSERT_TRUE(early->closing.has_value()) << "nobody can be shown an avatar of another generic face";
  EXPECT_EQ(early->closing->code, CloseCode::avatar_being_prepared);
  EXPECT_NE(early->closing->reason.find("join again in a few seconds"), std::string::npos) << early->closing->reason;

  ASSERT_TRUE(test::eventually([&] { return server.core().store().lookup(asset).avatar.has_value(); }, 60s))
      << server.core().store().lookup(asset).message;
  const auto joined = join_wearing(server, asset);
  ASSERT_TRUE(joined->welcome.has_value()) << (joined->closing ? joined->closing->reason : "");
  ASSERT_EQ(joined->welcome->avatars.size(), 1u);
  EXPECT_EQ(joined->welcome->avatars[0].asset, asset) << "the same id";

  const auto current = file_bytes(file(asset, ".fwa"));
  EXPECT_NE(current, older);
  EXPECT_EQ(*server.core().store().lookup(asset).avatar->full, current);
  model::AvatarPackage package;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(current, package, error)) << error;
  EXPECT_TRUE(model::parse_avatar_package(file_bytes(file(asset, ".preview.fwa")), package, error)) << error;
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo);

  const auto& metrics = server.core().metrics();
  EXPECT_EQ(metrics.repreparations_started.load(), 1u);
  EXPECT_TRUE(test::eventually([&] { return metrics.repreparations.load() == 1; }))
      << "counted once it is stored, which a join may beat";
  EXPECT_NE(metrics.render(1.0, server.core().abuse()).find("facewire_repreparations_total 1\n"), std::string::npos);
}

TEST_F(Repreparation, APhotoThatNoLongerMakesAnAvatarIsReportedAndRefused) {
  // An out-of-date avatar whose stored photo the preparer refuses (cut off).
  const std::string asset = "0123456789abcdef0123456789abcdef";
  store_out_of_date(asset, make_demo_package(1));
  const auto photo = file_bytes(test::test_photo("astronaut.png"));
  std::string error;
  ASSERT_TRUE(model::write_file_atomically(file(asset, ".photo"), std::span(photo).first(photo.size() / 2), error));

  InMemoryServer server(InMemoryServer::test_config(), data_);
  AvatarRepreparation repreparation(server.core().store(), *worker_);
  EXPECT_EQ(server.core().store().lookup(asset).status, AvatarStatus::being_prepared);
  ASSERT_TRUE(test::eventually(
      [&] { return server.core().store().lookup(asset).status != AvatarStatus::being_prepared; }, 60s));
  const AvatarLookup refused = server.core().store().lookup(asset);
  EXPECT_EQ(refused.status, AvatarStatus::out_of_date);
  EXPECT_NE(refused.message.find("upload your photo again"), std::string::npos) << refused.message;
  EXPECT_EQ(server.core().metrics().repreparation_failures.load(), 1u);
  const auto peer = join_wearing(server, asset);
  ASSERT_TRUE(peer->closing.has_value());
  EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
}

}  // namespace
}  // namespace fw::server
