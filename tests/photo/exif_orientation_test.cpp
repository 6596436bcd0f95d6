#include "exif_orientation.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace fw::photo {
namespace {

// An APP1 payload with one IFD0 entry: the orientation tag, as a SHORT.
std::vector<std::uint8_t> exif_with_orientation(int orientation, bool big_endian) {
  if (big_endian)
    return {'E', 'x', 'i', 'f', 0, 0, 'M', 'M', 0, 0x2A, 0, 0, 0, 8, 0, 1,
            0x01, 0x12, 0, 3, 0, 0, 0, 1, 0, static_cast<std::uint8_t>(orientation), 0, 0, 0, 0, 0, 0};
  return {'E', 'x', 'i', 'f', 0, 0, 'I', 'I', 0x2A, 0, 8, 0, 0, 0, 1, 0,
          0x12, 0x01, 3, 0, 1, 0, 0, 0, static_cast<std::uint8_t>(orientation), 0, 0, 0, 0, 0, 0, 0};
}

TEST(ExifOrientation, ReadsTheTagInBothByteOrders) {
  for (int orientation = 1; orientation <= 8; ++orientation) {
    EXPECT_EQ(exif_orientation(exif_with_orientation(orientation, false)), orientation);
    EXPECT_EQ(exif_orientation(exif_with_orientation(orientation, true)), orientation);
  }
}

TEST(ExifOrientation, AnythingElseIsAsStored) {
  EXPECT_EQ(exif_orientation({}), 1);
  auto out_of_range = exif_with_orientation(9, false);
  EXPECT_EQ(exif_orientation(out_of_range), 1);
  auto not_exif = exif_with_orientation(6, false);
  not_exif[0] = 'X';
  EXPECT_EQ(exif_orientation(not_exif), 1);
  // Every cut of a payload is read without reading past its end (the
  // sanitizer pass checks the "without").
  const auto whole = exif_with_orientation(6, true);
  for (std::size_t size = 0; size < whole.size(); ++size)
    EXPECT_EQ(exif_orientation(std::span(whole.data(), size)), size >= 26 ? 6 : 1) << size;
  // An IFD offset far past the end.
  auto far = exif_with_orientation(6, false);
  far[10] = 0xff;
  far[13] = 0x7f;
  EXPECT_EQ(exif_orientation(far), 1);
}

TEST(ExifOrientation, TurnsEachOrientationUpright) {
  // A 2x3 image stored as each orientation sees it; turned upright, each is
  // the same picture again.
  const cv::Mat upright = (cv::Mat_<std::uint8_t>(2, 3) << 1, 2, 3, 4, 5, 6);
  const auto stored_as = [&](int orientation) {
    cv::Mat m = upright.clone();
    switch (orientation) {
      case 2: cv::flip(m, m, 1); break;
      case 3: cv::flip(m, m, -1); break;
      case 4: cv::flip(m, m, 0); break;
      case 5: cv::transpose(m, m); break;
      case 6: cv::rotate(m, m, cv::ROTATE_90_COUNTERCLOCKWISE); break;
      case 7: cv::flip(m, m, -1); cv::transpose(m, m); break;
      case 8: cv::rotate(m, m, cv::ROTATE_90_CLOCKWISE); break;
      default: break;
    }
    return m;
  };
  for (int orientation = 1; orientation <= 8; ++orientation) {
    cv::Mat m = stored_as(orientation);
    turn_upright(m, orientation);
    ASSERT_EQ(m.size(), upright.size()) << orientation;
    EXPECT_EQ(cv::norm(m, upright, cv::NORM_INF), 0.0) << "orientation " << orientation;
  }
}

}  // namespace
}  // namespace fw::photo
