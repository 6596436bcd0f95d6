#pragma once
// Uploading one's face to the server before joining (PROTOCOL.md section 8,
// POST /api/avatars): a downsized photo, which the server turns into a
// package, or a prepared package. The answer's asset id goes into hello.
#include <cstdint>
#include <span>
#include <string>

namespace fw::client {

struct UploadTarget {
  std::string host;
  std::string port;  ///< the server's HTTP port
};

/// @param[in]  content_type  "image/jpeg", "image/png" or "application/x-facewire-avatar"
/// @param[in]  timeout_s     for the whole exchange (the server prepares a photo before it answers)
/// @param[out] asset         the asset id to use in hello
/// @param[out] error         the server's explanation (422: no face found, 413: too large, ...) or the I/O error
bool upload_avatar(const UploadTarget& target, const std::string& content_type, std::span<const std::uint8_t> body,
                   int timeout_s, std::string& asset, std::string& error);

}  // namespace fw::client
