#include "own_avatar.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/render/png.hpp"
#include "photo_downsizer.hpp"

namespace fw::client {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

// An uploader that records what it was given and answers with an asset id.
struct FakeUploader {
  int calls = 0;
  UploadTarget target;
  std::string content_type;
  Bytes body;
  int timeout_s = 0;

  AvatarUploader uploader() {
    return [this](const UploadTarget& t, const std::string& type, std::span<const std::uint8_t> b, int timeout,
                  UploadAnswer& answer, std::string&) {
      ++calls;
      target = t;
      content_type = type;
      body.assign(b.begin(), b.end());
      timeout_s = timeout;
      answer.asset = "asset42";
      answer.key = "key42";
      return true;
    };
  }
};

// A package the reader accepts: an identity fit, stand-in image bytes.
Bytes sample_package() {
  model::AvatarPackage p;
  p.generic_face_version = model::generic_face().version;
  for (const glm::vec3& v : model::generic_face().skin.positions) p.fitted_vertices.emplace_back(v.x, v.y);
  const auto landmarks = model::landmark_template();
  std::copy(landmarks.begin(), landmarks.end(), p.landmarks.begin());
  for (model::PackageImage* image : {&p.face_texture, &p.closed_lid, &p.eye, &p.mouth, &p.colour_masks_a,
                                     &p.colour_masks_b, &p.preview}) {
    image->type = "image/webp";
    image->bytes.assign(40, 1);
  }
  return model::serialize_avatar_package(p);
}

class OwnAvatarTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fw_own_avatar_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    args_.url = "ws://127.0.0.1:8080/";
    parse_server_url(args_.url, url_, error_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const Bytes& bytes) {
    std::ofstream(dir_ / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return (dir_ / name).string();
  }

  fs::path dir_;
  JoinArgs args_;
  ServerUrl url_;
  std::string error_;
  FakeUploader fake_;
};

TEST_F(OwnAvatarTest, WithoutAFaceNothingIsUploaded) {
  UploadedAvatar uploaded;
  ASSERT_TRUE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_)) << error_;
  EXPECT_EQ(fake_.calls, 0);
  EXPECT_TRUE(uploaded.asset.empty()) << "the server makes a face for the name";
}

TEST_F(OwnAvatarTest, APackageIsUploadedAsItIsAndKeptForTheOwnFace) {
  const Bytes package = sample_package();
  args_.avatar = write("me.fwa", package);
  UploadedAvatar uploaded;
  ASSERT_TRUE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_)) << error_;
  EXPECT_EQ(fake_.content_type, "application/x-facewire-avatar");
  EXPECT_EQ(fake_.body, package);
  EXPECT_EQ(fake_.target.host, "127.0.0.1");
  EXPECT_EQ(fake_.target.port, "8080");
  EXPECT_EQ(uploaded.asset, "asset42");
  EXPECT_EQ(uploaded.key, "key42") << "the key goes into the hello";
  EXPECT_EQ(uploaded.bytes, package.size());
  ASSERT_TRUE(uploaded.own_package);
  EXPECT_EQ(*uploaded.own_package, package);
}

TEST_F(OwnAvatarTest, APhotoGoesUpAsASmallJpeg) {
  model::RgbaImage photo(900, 600);
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      std::uint8_t* pixel = photo.at(x, y);
      pixel[0] = static_cast<std::uint8_t>(x);
      pixel[1] = static_cast<std::uint8_t>(y);
      pixel[2] = 90;
      pixel[3] = 255;
    }
  ASSERT_TRUE(render::write_png(photo, dir_ / "me.png", error_)) << error_;
  args_.photo = (dir_ / "me.png").string();
  UploadedAvatar uploaded;
  ASSERT_TRUE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_)) << error_;
  EXPECT_EQ(fake_.content_type, "image/jpeg");
  ASSERT_GE(fake_.body.size(), 2u);
  EXPECT_EQ(fake_.body[0], 0xFF);
  EXPECT_EQ(fake_.body[1], 0xD8);
  EXPECT_LE(fake_.body.size(), kTargetUploadBytes + kTargetUploadBytes / 10);
  EXPECT_FALSE(uploaded.own_package) << "the server prepares the package from a photo";
}

TEST_F(OwnAvatarTest, APackageCanTakeThePhotoItWasPreparedFromAlong) {
  const Bytes package = sample_package();
  args_.avatar = write("me.fwa", package);
  model::RgbaImage photo(64, 64);
  ASSERT_TRUE(render::write_png(photo, dir_ / "me.png", error_)) << error_;
  args_.photo = (dir_ / "me.png").string();
  UploadedAvatar uploaded;
  ASSERT_TRUE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_)) << error_;
  ASSERT_EQ(fake_.content_type.rfind("multipart/form-data; boundary=", 0), 0u) << fake_.content_type;
  const std::string boundary = fake_.content_type.substr(fake_.content_type.find('=') + 1);
  const std::string body(fake_.body.begin(), fake_.body.end());
  EXPECT_EQ(body.rfind("--" + boundary + "\r\nContent-Disposition: form-data; name=\"package\"", 0), 0u);
  EXPECT_NE(body.find(std::string(package.begin(), package.end())), std::string::npos);
  EXPECT_NE(body.find("name=\"photo\"\r\nContent-Type: image/jpeg\r\n\r\n\xFF\xD8"), std::string::npos);
  EXPECT_EQ(body.substr(body.size() - boundary.size() - 6), "--" + boundary + "--\r\n");
  ASSERT_TRUE(uploaded.own_package) << "the client draws its own face from the package";
  EXPECT_EQ(*uploaded.own_package, package);
}

TEST_F(OwnAvatarTest, WhatCannotBeReadIsNotUploaded) {
  UploadedAvatar uploaded;
  args_.avatar = write("broken.fwa", Bytes(100, 7));
  EXPECT_FALSE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_));
  EXPECT_EQ(error_.rfind("--avatar " + args_.avatar + ": ", 0), 0u) << error_;
  args_.avatar.clear();
  args_.photo = (dir_ / "missing.jpg").string();
  EXPECT_FALSE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_));
  EXPECT_EQ(error_.rfind("--photo: ", 0), 0u) << error_;
  args_.photo = write("text.jpg", Bytes{'h', 'i'});
  EXPECT_FALSE(upload_own_avatar(args_, url_, fake_.uploader(), uploaded, error_));
  EXPECT_NE(error_.find("the photo cannot be read"), std::string::npos) << error_;
  EXPECT_EQ(fake_.calls, 0);
}

TEST_F(OwnAvatarTest, UploadsGoToTheApiPortOrTheWebSocketsOwn) {
  UploadTarget target;
  ASSERT_TRUE(upload_target(args_, url_, target, error_));
  EXPECT_EQ(target.port, "8080");
  args_.api = "http://10.0.0.2:9000";
  ASSERT_TRUE(upload_target(args_, url_, target, error_)) << error_;
  EXPECT_EQ(target.host, "10.0.0.2");
  EXPECT_EQ(target.port, "9000");
  args_.api = "ftp://x";
  EXPECT_FALSE(upload_target(args_, url_, target, error_));
  EXPECT_EQ(error_.rfind("--api must look like http://HOST:PORT", 0), 0u) << error_;
  args_.api.clear();
  ServerUrl tcp;
  ASSERT_TRUE(parse_server_url("tcp://127.0.0.1:8081", tcp, error_));
  EXPECT_FALSE(upload_target(args_, tcp, target, error_));
  EXPECT_NE(error_.find("--api http://HOST:PORT"), std::string::npos) << error_;
}

TEST_F(OwnAvatarTest, EachServerOfAListHasItsUploadAddress) {
  std::vector<ServerUrl> servers(2);
  ASSERT_TRUE(parse_server_url("ws://10.0.0.1:8080/", servers[0], error_));
  ASSERT_TRUE(parse_server_url("tcp://10.0.0.2:8081", servers[1], error_));
  std::vector<UploadTarget> targets;
  EXPECT_FALSE(upload_targets(args_, servers, targets, error_)) << "a tcp:// server needs --api";
  EXPECT_NE(error_.find("--api http://HOST:PORT"), std::string::npos) << error_;
  args_.api = "http://10.0.0.9:9000";
  ASSERT_TRUE(upload_targets(args_, servers, targets, error_)) << error_;
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_EQ(targets[0].host, "10.0.0.9") << "one --api for every server";
  EXPECT_EQ(targets[1].host, "10.0.0.9");
  args_.api = "http://10.0.0.1:8080, http://10.0.0.2:8080";
  ASSERT_TRUE(upload_targets(args_, servers, targets, error_)) << error_;
  EXPECT_EQ(targets[0].host, "10.0.0.1") << "or one each, in the same order";
  EXPECT_EQ(targets[1].host, "10.0.0.2");
  args_.api = "http://a:1,http://b:2,http://c:3";
  EXPECT_FALSE(upload_targets(args_, servers, targets, error_));
  EXPECT_EQ(error_, "--api names 3 HTTP addresses for 2 servers: give one for them all, or one per server in the same order");
}

TEST_F(OwnAvatarTest, AServerThatDoesNotAnswerPassesTheUploadToTheNext) {
  std::vector<ServerUrl> servers(3);
  for (int i = 0; i < 3; ++i)
    ASSERT_TRUE(parse_server_url("ws://10.0.0." + std::to_string(i + 1) + ":8080/", servers[static_cast<std::size_t>(i)], error_));
  args_.avatar = write("me.fwa", sample_package());
  std::vector<std::string> asked;
  int refuse_with = 0;  // the second server's answer: 0 none, else an HTTP status
  AvatarUploader uploader = [&](const UploadTarget& target, const std::string&, std::span<const std::uint8_t>, int,
                                UploadAnswer& answer, std::string& error) {
    asked.push_back(target.host);
    if (target.host == "10.0.0.3" || (target.host == "10.0.0.2" && refuse_with == 0)) {
      error = "Connection refused";
      return false;
    }
    if (target.host == "10.0.0.2") {
      answer.http_status = refuse_with;
      error = "refused (" + std::to_string(refuse_with) + ")";
      return false;
    }
    answer = {"asset-a", "key-a", 201};
    return true;
  };
  // The first is down, the second takes it.
  std::rotate(servers.begin(), servers.begin() + 1, servers.end());  // 10.0.0.2, 10.0.0.3, 10.0.0.1
  OwnAvatar own;
  ASSERT_TRUE(prepare_own_avatar(args_, own, error_)) << error_;
  UploadedAvatar uploaded;
  ASSERT_TRUE(upload_prepared_avatar(args_, servers, uploader, own, uploaded, error_)) << error_;
  EXPECT_EQ(asked, (std::vector<std::string>{"10.0.0.2", "10.0.0.3", "10.0.0.1"}));
  EXPECT_EQ(uploaded.server, 2u);
  EXPECT_EQ(uploaded.asset, "asset-a");
  ASSERT_TRUE(uploaded.body) << "kept for a server that does not know the face";
  EXPECT_EQ(uploaded.content_type, "application/x-facewire-avatar");
  // A busy server passes it on too; a refusal that is the same anywhere does not.
  asked.clear();
  refuse_with = 503;
  ASSERT_TRUE(upload_prepared_avatar(args_, servers, uploader, own, uploaded, error_)) << error_;
  EXPECT_EQ(asked.size(), 3u);
  asked.clear();
  refuse_with = 422;
  EXPECT_FALSE(upload_prepared_avatar(args_, servers, uploader, own, uploaded, error_));
  EXPECT_EQ(asked, std::vector<std::string>{"10.0.0.2"});
  EXPECT_EQ(error_, "refused (422)");
  // None answers: every server's reason.
  servers.pop_back();
  refuse_with = 0;
  EXPECT_FALSE(upload_prepared_avatar(args_, servers, uploader, own, uploaded, error_));
  EXPECT_EQ(error_, "no server took the upload of your face: ws://10.0.0.2:8080/: Connection refused; "
                    "ws://10.0.0.3:8080/: Connection refused");
}

TEST(OwnAvatar, ASlowLinkGetsTimeForTheBytes) {
  EXPECT_EQ(upload_timeout_s(30000, 0), 60);
  EXPECT_EQ(upload_timeout_s(30000, 9.6), 60 + 25);
}

}  // namespace
}  // namespace fw::client
