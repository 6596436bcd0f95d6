// One upload of a package with the photo it was prepared from.
#include "package_with_photo.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(PackageWithPhoto, ChoosesABoundaryThatNeitherPartHolds) {
  const std::string usual = "facewire-avatar-" + std::string(16, 'x');
  const std::string awkward = "FWAV " + usual + "x" + " end";
  const std::vector<std::uint8_t> package(awkward.begin(), awkward.end());
  const std::vector<std::uint8_t> photo = {0xFF, 0xD8, 0xFF};
  const MultipartUpload upload = package_with_photo(package, photo, "image/jpeg");
  const std::string boundary = upload.content_type.substr(upload.content_type.find("boundary=") + 9);
  EXPECT_EQ(boundary, usual + "xx");
  const std::string body(upload.body.begin(), upload.body.end());
  EXPECT_EQ(body, "--" + boundary + "\r\nContent-Disposition: form-data; name=\"package\"\r\n"
                  "Content-Type: application/x-facewire-avatar\r\n\r\n" + awkward + "\r\n--" + boundary +
                  "\r\nContent-Disposition: form-data; name=\"photo\"\r\nContent-Type: image/jpeg\r\n\r\n\xFF\xD8\xFF"
                  "\r\n--" + boundary + "--\r\n");
}

}  // namespace
}  // namespace fw::client
