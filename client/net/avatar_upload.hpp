#pragma once
// Uploading one's face to the server before joining (PROTOCOL.md section 8,
// POST /api/avatars) over HTTP: the AvatarUploader (avatar_uploader.hpp)
// of facewire-client (socket glue, so only the program links it). join's
// own_avatar.hpp prepares what goes up. The session uploads the face again
// to another server of the list that does not know it, on its own
// io_context (async_upload_avatar).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>

#include "avatar_uploader.hpp"

namespace fw::client {

/// @param[in]  content_type  "image/jpeg", "image/png" or "application/x-facewire-avatar"
/// @param[in]  timeout_s     for the whole exchange (the server prepares a photo before it answers)
/// @param[out] answer        the asset id and its key, to use in hello; the HTTP status either way
/// @param[out] error         the server's explanation (422: no face found, 413: too large, ...) or the I/O error
bool upload_avatar(const UploadTarget& target, const std::string& content_type, std::span<const std::uint8_t> body,
                   int timeout_s, UploadAnswer& answer, std::string& error);

/// The same on `io`, without blocking: `done(ok, answer, error)` runs on
/// `io` when the exchange is over (an AsyncAvatarUploader).
void async_upload_avatar(boost::asio::io_context& io, const UploadTarget& target, const std::string& content_type,
                         std::shared_ptr<const std::vector<std::uint8_t>> body, int timeout_s,
                         std::function<void(bool ok, const UploadAnswer& answer, const std::string& error)> done);

}  // namespace fw::client
