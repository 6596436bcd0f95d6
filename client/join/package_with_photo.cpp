#include "package_with_photo.hpp"

#include <algorithm>

namespace fw::client {
namespace {

bool contains(std::span<const std::uint8_t> bytes, const std::string& text) {
  return std::search(bytes.begin(), bytes.end(), text.begin(), text.end()) != bytes.end();
}

void append(std::vector<std::uint8_t>& out, const std::string& text) {
  out.insert(out.end(), text.begin(), text.end());
}

}  // namespace

MultipartUpload package_with_photo(std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo,
                                   const std::string& photo_type) {
  // A boundary must not occur in either part; binary data seldom holds a
  // long run of one letter, and a longer one is tried until neither does.
  std::string boundary = "facewire-avatar-" + std::string(16, 'x');
  while (contains(package, boundary) || contains(photo, boundary)) boundary += 'x';
  MultipartUpload upload{"multipart/form-data; boundary=" + boundary, {}};
  const auto part = [&](const char* name, const std::string& type, std::span<const std::uint8_t> data) {
    append(upload.body, "--" + boundary + "\r\nContent-Disposition: form-data; name=\"" + name +
                            "\"\r\nContent-Type: " + type + "\r\n\r\n");
    upload.body.insert(upload.body.end(), data.begin(), data.end());
    append(upload.body, "\r\n");
  };
  part("package", "application/x-facewire-avatar", package);
  part("photo", photo_type, photo);
  append(upload.body, "--" + boundary + "--\r\n");
  return upload;
}

}  // namespace fw::client
