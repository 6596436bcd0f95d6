#pragma once
// A prepared package and the photo it was prepared from, in one upload
// (PROTOCOL.md section 8: multipart/form-data with the parts `package` and
// `photo`), so that the server keeps the photo and can prepare the avatar
// again when its package format or generic face changes.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace fw::client {

struct MultipartUpload {
  std::string content_type;  ///< multipart/form-data with its boundary
  std::vector<std::uint8_t> body;
};

/// @param package     the .fwa bytes
/// @param photo       the downsized photo
/// @param photo_type  its media type ("image/jpeg")
MultipartUpload package_with_photo(std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo,
                                   const std::string& photo_type);

}  // namespace fw::client
