// Stored avatars of an older generic face prepared again from the photo kept
// beside them, with the real preparer on the astronaut portrait, through the
// server core and in-memory connections: the upload keeps its photo, a
// restarted server serves the avatar again under the same id, and a join
// meanwhile gets the temporary answer. One process (the landmark model loads
// once, on the photo worker all the tests share).
#include "avatar_repreparation.hpp"

#include <filesystem>
#include <future>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demo_faces.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "in_memory_server.hpp"
#include "photo_preparation.hpp"
#include "photo_worker.hpp"
#include "rest_api.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using codec::CloseCode;
using test::InMemoryServer;
namespace http = boost::beast::http;

std::vector<std::uint8_t> file_bytes(const std::filesystem::path& path) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  EXPECT_TRUE(model::read_file(path, 64 << 20, bytes, error)) << error;
  return bytes;
}

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

  /// POST /api/avatars with `body`, as the HTTP session hands it over.
  static Response upload(PhotoPreparation& uploads, const std::string& type, std::span<const std::uint8_t> body) {
    Request request{http::verb::post, "/api/avatars", 11};
    request.set(http::field::content_type, type);
    request.body().assign(body.begin(), body.end());
    std::promise<Response> answer;
    uploads.upload(std::move(request), "127.0.0.1", [&answer](Response response) { answer.set_value(response); });
    return answer.get_future().get();
  }

  /// What a build with the previous generic face stored: the same avatar, fitted to it.
  void make_out_of_date(const std::string& asset) const {
    model::AvatarPackage package;
    std::string error;
    ASSERT_TRUE(model::parse_avatar_package(file_bytes(file(asset, ".fwa")), package, error)) << error;
    package.generic_face_version -= 1;
    const auto older = model::serialize_avatar_package(package);
    ASSERT_TRUE(model::write_file_atomically(file(asset, ".fwa"), older, error)) << error;
  }

  static std::unique_ptr<test::InMemoryPeer> join_wearing(InMemoryServer& server, const std::string& asset) {
    test::HelloOptions options;
    options.avatar = asset;
    return server.join("r", "Ann", options);
  }

  static Response get(ServerContext& context, const std::string& target) {
    return *respond_to_api(context, Request{http::verb::get, target, 11});
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
    PhotoPreparation uploads(server.context(), *worker_);
    const Response answer = upload(uploads, "image/png", photo);
    ASSERT_EQ(answer.result(), http::status::created) << answer.body();
    asset = nlohmann::json::parse(answer.body())["asset"];
  }
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo) << "the photo as uploaded, beside its package";

  // The server is upgraded to a new generic face; it had crashed once while
  // writing this package (its temporary file is still there).
  make_out_of_date(asset);
  const auto older = file_bytes(file(asset, ".fwa"));
  std::filesystem::copy_file(file(asset, ".fwa"), file(asset, ".fwa.partial-4242"));

  InMemoryServer server(InMemoryServer::test_config(), data_);
  AvatarRepreparation repreparation(server.context(), *worker_);
  const auto early = join_wearing(server, asset);
  ASSERT_TRUE(early->closing.has_value()) << "nobody can be shown an avatar of another generic face";
  EXPECT_EQ(early->closing->code, CloseCode::avatar_being_prepared);
  EXPECT_NE(early->closing->reason.find("join again in a few seconds"), std::string::npos) << early->closing->reason;
  const Response busy = get(server.context(), "/api/packages/" + asset);
  EXPECT_EQ(busy.result(), http::status::service_unavailable) << busy.body();
  EXPECT_EQ(busy[http::field::retry_after], "5");

  ASSERT_TRUE(test::eventually([&] { return server.context().store->lookup(asset).avatar.has_value(); }, 60s))
      << server.context().store->lookup(asset).message;
  const auto joined = join_wearing(server, asset);
  ASSERT_TRUE(joined->welcome.has_value()) << (joined->closing ? joined->closing->reason : "");
  ASSERT_EQ(joined->welcome->avatars.size(), 1u);
  EXPECT_EQ(joined->welcome->avatars[0].asset, asset) << "the same id";

  const auto current = file_bytes(file(asset, ".fwa"));
  EXPECT_NE(current, older);
  model::AvatarPackage package;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(current, package, error)) << error;
  EXPECT_TRUE(model::parse_avatar_package(file_bytes(file(asset, ".preview.fwa")), package, error)) << error;
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo);
  const Response served = get(server.context(), "/api/packages/" + asset);
  EXPECT_EQ(served.result(), http::status::ok);
  EXPECT_EQ(served.body(), std::string(current.begin(), current.end()));
  EXPECT_EQ(served[http::field::etag], "\"" + server.context().store->lookup(asset).avatar->version + "\"");

  const auto& metrics = server.context().metrics;
  EXPECT_EQ(metrics.repreparations_started.load(), 1u);
  EXPECT_TRUE(test::eventually([&] { return metrics.repreparations.load() == 1; }))
      << "counted once it is stored, which a join may beat";
  EXPECT_NE(get(server.context(), "/metrics").body().find("facewire_repreparations_total 1\n"), std::string::npos);
}

TEST_F(Repreparation, APackageUploadedWithItsPhotoKeepsThePhoto) {
  const auto package = make_demo_package(2);
  const auto photo = file_bytes(test::test_photo("grace_hopper.jpg"));
  const std::string boundary = "facewire-avatar-xxxxxxxxxxxxxxxx";
  std::string body = "--" + boundary +
                     "\r\nContent-Disposition: form-data; name=\"package\"\r\n"
                     "Content-Type: application/x-facewire-avatar\r\n\r\n" +
                     std::string(package.begin(), package.end()) + "\r\n--" + boundary +
                     "\r\nContent-Disposition: form-data; name=\"photo\"; filename=\"me.jpg\"\r\n"
                     "Content-Type: image/jpeg\r\n\r\n" +
                     std::string(photo.begin(), photo.end()) + "\r\n--" + boundary + "--\r\n";
  InMemoryServer server(InMemoryServer::test_config(), data_);
  PhotoPreparation uploads(server.context(), *worker_);
  const std::vector<std::uint8_t> bytes(body.begin(), body.end());
  const Response answer = upload(uploads, "multipart/form-data; boundary=\"" + boundary + "\"", bytes);
  ASSERT_EQ(answer.result(), http::status::created) << answer.body();
  const std::string asset = nlohmann::json::parse(answer.body())["asset"];
  EXPECT_EQ(file_bytes(file(asset, ".fwa")), package);
  EXPECT_EQ(file_bytes(file(asset, ".photo")), photo);

  // Malformed or incomplete: refused with what to send.
  const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + 200);
  const Response truncated = upload(uploads, "multipart/form-data; boundary=" + boundary, cut);
  EXPECT_EQ(truncated.result(), http::status::bad_request);
  EXPECT_NE(truncated.body().find("cut off"), std::string::npos) << truncated.body();
  const std::string photo_only = body.substr(body.find("\r\n--" + boundary) + 2);
  const Response no_package = upload(uploads, "multipart/form-data; boundary=" + boundary,
                                     std::vector<std::uint8_t>(photo_only.begin(), photo_only.end()));
  EXPECT_EQ(no_package.result(), http::status::bad_request);
  EXPECT_NE(no_package.body().find("'package'"), std::string::npos) << no_package.body();
}

TEST_F(Repreparation, APhotoThatNoLongerMakesAnAvatarIsReportedAndRefused) {
  // An out-of-date avatar whose stored photo the preparer refuses (cut off).
  const std::string asset = "0123456789abcdef0123456789abcdef";
  std::filesystem::create_directories(data_ / "avatars");
  model::AvatarPackage package;
  std::string error;
  ASSERT_TRUE(model::parse_avatar_package(make_demo_package(1), package, error)) << error;
  package.generic_face_version -= 1;
  ASSERT_TRUE(model::write_file_atomically(file(asset, ".fwa"), model::serialize_avatar_package(package), error));
  const auto photo = file_bytes(test::test_photo("astronaut.png"));
  ASSERT_TRUE(model::write_file_atomically(file(asset, ".photo"), std::span(photo).first(photo.size() / 2), error));

  InMemoryServer server(InMemoryServer::test_config(), data_);
  AvatarRepreparation repreparation(server.context(), *worker_);
  EXPECT_EQ(server.context().store->lookup(asset).status, AvatarStatus::being_prepared);
  ASSERT_TRUE(test::eventually(
      [&] { return server.context().store->lookup(asset).status != AvatarStatus::being_prepared; }, 60s));
  const AvatarLookup refused = server.context().store->lookup(asset);
  EXPECT_EQ(refused.status, AvatarStatus::out_of_date);
  EXPECT_NE(refused.message.find("upload your photo again"), std::string::npos) << refused.message;
  EXPECT_EQ(server.context().metrics.repreparation_failures.load(), 1u);
  const auto peer = join_wearing(server, asset);
  ASSERT_TRUE(peer->closing.has_value());
  EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
  EXPECT_EQ(get(server.context(), "/api/packages/" + asset).result(), http::status::gone);
}

}  // namespace
}  // namespace fw::server
