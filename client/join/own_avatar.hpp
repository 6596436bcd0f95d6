#pragma once
// The face the joining person brings (`--photo` or `--avatar`) and its way
// to the server (PROTOCOL.md section 8, POST /api/avatars): a photo made
// small for a slow link, or a package checked before it is sent; where the
// upload goes; how long it may take. The HTTP exchange itself is an
// AvatarUploader (transport's avatar_uploader.hpp; net's avatar_upload.hpp
// in facewire-client); the answer's asset id goes into hello.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "avatar_uploader.hpp"
#include "join_arguments.hpp"
#include "server_url.hpp"

namespace fw::client {

/// What goes up: the downsized photo, the package as it was read, or both.
struct OwnAvatar {
  std::string content_type;  ///< "image/jpeg", "application/x-facewire-avatar" or multipart/form-data
  std::vector<std::uint8_t> bytes;    ///< the upload's body
  std::vector<std::uint8_t> package;  ///< the package, when one goes up (the client draws its own face from it)
  std::vector<std::uint8_t> photo;    ///< the downsized photo (JPEG), when one goes up: the self view until the face comes
};

/// What came of the upload.
struct UploadedAvatar {
  std::string asset;         ///< for hello; empty: the server makes a face for the name
  std::string key;           ///< the asset's key, for hello
  std::size_t bytes = 0;     ///< uploaded
  std::size_t server = 0;    ///< the index of the server that took it (of several: the first that answered)
  /// What went up, for a server of the list that does not know the face.
  std::string content_type;
  std::shared_ptr<const std::vector<std::uint8_t>> body;
  /// The package, when one was uploaded: the client draws its own face from it.
  std::shared_ptr<const std::vector<std::uint8_t>> own_package;
};

/// Whether the command line brings a face of its own (--photo or --avatar).
inline bool brings_own_avatar(const JoinArgs& args) { return !args.photo.empty() || !args.avatar.empty(); }

/// Where uploads go: --api, or the ws:// URL's own host and port (the
/// WebSocket shares the HTTP port). A tcp:// URL needs --api.
bool upload_target(const JoinArgs& args, const ServerUrl& url, UploadTarget& target, std::string& error);
/// The same for each of several servers: --api names one HTTP address for
/// them all, or one per server in the same order (comma-separated).
bool upload_targets(const JoinArgs& args, const std::vector<ServerUrl>& servers, std::vector<UploadTarget>& targets,
                    std::string& error);

/// Reads --photo (decoded, downsized, re-encoded as JPEG), --avatar (a
/// package that must parse), or both (the package with the photo it was
/// prepared from, so the server keeps the photo; PROTOCOL.md section 8).
/// @return false and `error` saying what to change.
bool prepare_own_avatar(const JoinArgs& args, OwnAvatar& avatar, std::string& error);

/// Seconds an upload of `bytes` may take: a photo is prepared on the server
/// before it answers, and a slow link (`max_kbps`, 0: unknown) needs its
/// time for the bytes.
int upload_timeout_s(std::size_t bytes, double max_kbps);

/// The whole step: with neither --photo nor --avatar nothing is uploaded
/// (and `uploaded` stays empty); else prepare, then upload through `uploader`.
bool upload_own_avatar(const JoinArgs& args, const ServerUrl& url, const AvatarUploader& uploader,
                       UploadedAvatar& uploaded, std::string& error);
/// The upload alone, of an avatar prepare_own_avatar made (so that the
/// self view can show it while the upload runs).
bool upload_prepared_avatar(const JoinArgs& args, const ServerUrl& url, const AvatarUploader& uploader,
                            OwnAvatar avatar, UploadedAvatar& uploaded, std::string& error);
/// The same with several servers: each in turn until one takes it. A
/// server that does not answer, or is busy or draining, passes it to the
/// next; a refusal (no face in the photo, a bad token) is the same
/// everywhere and ends the step. `uploaded.server` says which took it.
bool upload_prepared_avatar(const JoinArgs& args, const std::vector<ServerUrl>& servers,
                            const AvatarUploader& uploader, OwnAvatar avatar, UploadedAvatar& uploaded,
                            std::string& error);

}  // namespace fw::client
