#include "own_avatar.hpp"

#include "fw/model/avatar_package.hpp"
#include "failover_policy.hpp"
#include "fw/model/file_io.hpp"
#include "package_with_photo.hpp"
#include "photo_downsizer.hpp"
#include "server_list.hpp"

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

bool upload_targets(const JoinArgs& args, const std::vector<ServerUrl>& servers, std::vector<UploadTarget>& targets,
                    std::string& error) {
  const std::vector<std::string> apis = args.api.empty() ? std::vector<std::string>{} : split_at_commas(args.api);
  if (apis.size() > 1 && apis.size() != servers.size()) {
    error = "--api names " + std::to_string(apis.size()) + " HTTP addresses for " + std::to_string(servers.size()) +
            " servers: give one for them all, or one per server in the same order";
    return false;
  }
  std::vector<UploadTarget> found(servers.size());
  for (std::size_t i = 0; i < servers.size(); ++i) {
    JoinArgs one = args;
    one.api = apis.empty() ? "" : apis[apis.size() == 1 ? 0 : i];
    if (!upload_target(one, servers[i], found[i], error)) return false;
  }
  targets = std::move(found);
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
  return upload_prepared_avatar(args, std::vector<ServerUrl>{url}, uploader, std::move(avatar), uploaded, error);
}

bool upload_prepared_avatar(const JoinArgs& args, const std::vector<ServerUrl>& servers,
                            const AvatarUploader& uploader, OwnAvatar avatar, UploadedAvatar& uploaded,
                            std::string& error) {
  if (!brings_own_avatar(args)) return true;
  std::vector<UploadTarget> targets;
  if (!upload_targets(args, servers, targets, error)) return false;
  const int timeout_s = upload_timeout_s(avatar.bytes.size(), args.max_kbps);
  std::string failures;  // of the servers that did not take it, for when none did
  for (std::size_t i = 0; i < targets.size(); ++i) {
    UploadAnswer answer;
    std::string why;
    if (!uploader(targets[i], avatar.content_type, avatar.bytes, timeout_s, answer, why)) {
      if (servers.size() == 1 || !another_server_may_take_it(answer.http_status)) {
        error = std::move(why);
        return false;
      }
      failures += (failures.empty() ? "" : "; ") + servers[i].text + ": " + why;
      continue;
    }
    uploaded.asset = std::move(answer.asset);
    uploaded.key = std::move(answer.key);
    uploaded.bytes = avatar.bytes.size();
    uploaded.server = i;
    uploaded.content_type = avatar.content_type;
    uploaded.body = std::make_shared<const std::vector<std::uint8_t>>(std::move(avatar.bytes));
    if (!avatar.package.empty())
      uploaded.own_package = std::make_shared<const std::vector<std::uint8_t>>(std::move(avatar.package));
    return true;
  }
  error = "no server took the upload of your face: " + failures;
  return false;
}

}  // namespace fw::client
