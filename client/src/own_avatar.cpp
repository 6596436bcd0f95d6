#include "own_avatar.hpp"

#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "package_with_photo.hpp"
#include "photo_downsizer.hpp"

namespace fw::client {
namespace {

bool read_photo(const std::string& path, OwnAvatar& avatar, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (!model::read_file(path, kMaxPhotoFileBytes, bytes, error)) {
    error = "--photo: " + error;
    return false;
  }
  DownsizedPhoto photo;
  if (!downsize_photo(bytes, photo, error)) {
    error = "--photo " + path + ": " + error;
    return false;
  }
  avatar.photo = std::move(photo.jpeg);
  avatar.bytes = avatar.photo;
  avatar.content_type = "image/jpeg";
  return true;
}

bool read_package(const std::string& path, OwnAvatar& avatar, std::string& error) {
  if (!model::read_file(path, model::kMaxPackageBytes, avatar.package, error)) {
    error = "--avatar: " + error;
    return false;
  }
  model::AvatarPackage package;
  if (!model::parse_avatar_package(avatar.package, package, error)) {
    error = "--avatar " + path + ": " + error;
    return false;
  }
  avatar.content_type = "application/x-facewire-avatar";
  avatar.bytes = avatar.package;
  return true;
}

// Both: the package goes up with the photo it was prepared from.
bool read_package_and_photo(const JoinArgs& args, OwnAvatar& avatar, std::string& error) {
  OwnAvatar photo;
  if (!read_package(args.avatar, avatar, error) || !read_photo(args.photo, photo, error)) return false;
  MultipartUpload upload = package_with_photo(avatar.package, photo.bytes, photo.content_type);
  avatar.content_type = std::move(upload.content_type);
  avatar.bytes = std::move(upload.body);
  avatar.photo = std::move(photo.photo);
  return true;
}

}  // namespace

bool upload_target(const JoinArgs& args, const ServerUrl& url, UploadTarget& target, std::string& error) {
  if (!args.api.empty()) {
    ServerUrl api;
    std::string as_ws = args.api;
    if (as_ws.rfind("http://", 0) == 0) as_ws.replace(0, 7, "ws://");
    if (!parse_server_url(as_ws, api, error) || api.scheme != ServerUrl::Scheme::websocket) {
      error = "--api must look like http://HOST:PORT (the server's HTTP port), not '" + args.api + "'";
      return false;
    }
    target = {api.host, api.port, args.token};
    return true;
  }
  if (url.scheme == ServerUrl::Scheme::tcp) {
    error = "a tcp:// URL names the stream port only: say where the server's HTTP port is with --api "
            "http://HOST:PORT so that the photo or package can be uploaded";
    return false;
  }
  target = {url.host, url.port, args.token};
  return true;
}

bool prepare_own_avatar(const JoinArgs& args, OwnAvatar& avatar, std::string& error) {
  if (!args.photo.empty() && !args.avatar.empty()) return read_package_and_photo(args, avatar, error);
  return args.photo.empty() ? read_package(args.avatar, avatar, error) : read_photo(args.photo, avatar, error);
}

int upload_timeout_s(std::size_t bytes, double max_kbps) {
  return 60 + static_cast<int>(max_kbps > 0 ? static_cast<double>(bytes) * 8 / (max_kbps * 1000) : 0);
}

bool upload_own_avatar(const JoinArgs& args, const ServerUrl& url, const AvatarUploader& uploader,
                       UploadedAvatar& uploaded, std::string& error) {
  if (!brings_own_avatar(args)) return true;
  UploadTarget target;
  OwnAvatar avatar;
  if (!upload_target(args, url, target, error) || !prepare_own_avatar(args, avatar, error)) return false;
  return upload_prepared_avatar(args, url, uploader, std::move(avatar), uploaded, error);
}

bool upload_prepared_avatar(const JoinArgs& args, const ServerUrl& url, const AvatarUploader& uploader,
                            OwnAvatar avatar, UploadedAvatar& uploaded, std::string& error) {
  if (!brings_own_avatar(args)) return true;
  UploadTarget target;
  if (!upload_target(args, url, target, error)) return false;
  const int timeout_s = upload_timeout_s(avatar.bytes.size(), args.max_kbps);
  UploadAnswer answer;
  if (!uploader(target, avatar.content_type, avatar.bytes, timeout_s, answer, error)) return false;
  uploaded.asset = std::move(answer.asset);
  uploaded.key = std::move(answer.key);
  uploaded.bytes = avatar.bytes.size();
  if (!avatar.package.empty())
    uploaded.own_package = std::make_shared<const std::vector<std::uint8_t>>(std::move(avatar.package));
  return true;
}

}  // namespace fw::client
