#pragma once
// The seam of the avatar upload (PROTOCOL.md section 8, POST /api/avatars):
// where an upload goes, what the server answers, and the upload itself as a
// function. The parts that decide what goes up and when (join's own_avatar,
// the session's upload to another server) take such a function; the HTTP
// exchange behind it is net's avatar_upload.hpp, which only the program
// links, and the tests pass their own.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>

namespace fw::client {

struct UploadTarget {
  std::string host;
  std::string port;   ///< the server's HTTP port
  std::string token;  ///< the join token, sent as a bearer token: a server with --auth-secret wants it
};

/// The server's answer to an upload.
struct UploadAnswer {
  std::string asset;  ///< the asset id, for hello
  std::string key;    ///< the secret that lets this client wear the face, for hello
  int http_status = 0;  ///< the answer's status, also when it refused; 0 when none came
};

/// Posts `body` to the target's /api/avatars within `timeout_s`; true and
/// the answer, or false and what went wrong (the server's explanation).
using AvatarUploader = std::function<bool(const UploadTarget& target, const std::string& content_type,
                                          std::span<const std::uint8_t> body, int timeout_s, UploadAnswer& answer,
                                          std::string& error)>;
/// The same on `io` (the session's, while it runs): `done(ok, answer, error)`
/// runs there when the upload is over.
using AsyncAvatarUploader = std::function<void(
    boost::asio::io_context& io, const UploadTarget& target, const std::string& content_type,
    std::shared_ptr<const std::vector<std::uint8_t>> body, int timeout_s,
    std::function<void(bool ok, const UploadAnswer& answer, const std::string& error)> done)>;

}  // namespace fw::client
