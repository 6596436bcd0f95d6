// The multipart/form-data reader behind uploads of a package with its photo.
#include "multipart_body.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

std::span<const std::uint8_t> bytes_of(const std::string& text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

std::string text_of(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

TEST(MultipartBody, FindsTheBoundaryQuotedOrNot) {
  EXPECT_EQ(multipart_boundary("multipart/form-data; boundary=abc"), "abc");
  EXPECT_EQ(multipart_boundary("Multipart/Form-Data; charset=utf-8; Boundary=\"a b;c\""), "a b;c");
  EXPECT_EQ(multipart_boundary("multipart/form-data"), "");
  EXPECT_EQ(multipart_boundary("image/png; boundary=abc"), "") << "another type";
}

TEST(MultipartBody, ReadsEachPartByItsName) {
  const std::string body =
      "--B\r\ncontent-disposition: form-data; filename=\"x.fwa\"; name=\"package\"\r\n\r\nFW\r\n--\r\nAV"
      "\r\n--B\r\nContent-Disposition: form-data; name=photo\r\nContent-Type: IMAGE/JPEG; q=1\r\n\r\n\xFF\xD8"
      "\r\n--B--\r\n";
  std::map<std::string, MultipartPart> parts;
  std::string error;
  ASSERT_TRUE(read_multipart(bytes_of(body), "B", parts, error)) << error;
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(text_of(parts["package"].data), "FW\r\n--\r\nAV") << "a dash line that is not the boundary is data";
  EXPECT_EQ(parts["package"].content_type, "");
  EXPECT_EQ(text_of(parts["photo"].data), "\xFF\xD8");
  EXPECT_EQ(parts["photo"].content_type, "image/jpeg");
}

TEST(MultipartBody, SaysWhatIsMalformed) {
  const auto error_of = [](const std::string& body) {
    std::map<std::string, MultipartPart> parts;
    std::string error;
    EXPECT_FALSE(read_multipart(bytes_of(body), "B", parts, error)) << body;
    return error;
  };
  EXPECT_NE(error_of("junk").find("does not start with its boundary"), std::string::npos);
  EXPECT_NE(error_of("--B\r\nContent-Disposition: form-data; name=a\r\n\r\nxyz").find("cut off"), std::string::npos);
  EXPECT_NE(error_of("--B\r\nContent-Type: image/png\r\n\r\nx\r\n--B--").find("no form name"), std::string::npos);
  EXPECT_NE(error_of("--B\r\nContent-Disposition: form-data; name=a\r\n\r\nx\r\n--B\r\n"
                     "Content-Disposition: form-data; name=a\r\n\r\ny\r\n--B--")
                .find("two parts named 'a'"),
            std::string::npos);
  EXPECT_NE(error_of("--B\r\nContent-Disposition: form-data; name=a\r\n\r\nx\r\n--B").find("closing boundary"),
            std::string::npos);
}

}  // namespace
}  // namespace fw::server
