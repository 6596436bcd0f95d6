// The head as a star-shaped region: holes filled, a thin scrap beside it
// dropped by the median across rays, a notch in its edge filled.
#include "star_shaped_region.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace fw::photo {
namespace {

constexpr int kSize = 101;
const cv::Point2f kCentre(50.0f, 50.0f);

cv::Mat disc(int radius) {
  cv::Mat region(kSize, kSize, CV_8U, cv::Scalar(0));
  cv::circle(region, cv::Point(50, 50), radius, cv::Scalar(255), cv::FILLED);
  return region;
}

TEST(StarShapedRegion, HolesAreFilledAndTheOutsideIsNot) {
  cv::Mat region = disc(30);
  cv::circle(region, cv::Point(60, 50), 5, cv::Scalar(0), cv::FILLED);
  const cv::Mat filled = fill_holes(region);
  EXPECT_EQ(filled.at<std::uint8_t>(50, 60), 255);
  EXPECT_EQ(filled.at<std::uint8_t>(5, 5), 0);
  EXPECT_EQ(cv::countNonZero(filled), cv::countNonZero(disc(30)));
}

TEST(StarShapedRegion, AThinScrapGoesAndANotchIsFilled) {
  cv::Mat region = disc(30);
  // A scrap 3 pixels wide reaching out to the right, a notch cut in on the left.
  cv::rectangle(region, cv::Rect(78, 49, 20, 3), cv::Scalar(255), cv::FILLED);
  cv::rectangle(region, cv::Rect(20, 49, 8, 3), cv::Scalar(0), cv::FILLED);
  constexpr int kRays = 180;
  const std::vector<float> raw = ray_reach(region, kCentre, kRays, 0.0f);
  EXPECT_GT(raw[0], 40.0f) << "along the scrap";
  EXPECT_LT(raw[kRays / 2], 25.0f) << "into the notch";
  const std::vector<float> smooth = median_across_rays(raw, 4);
  for (const float r : smooth) EXPECT_NEAR(r, 30.0f, 1.5f);
  const cv::Mat redrawn = fill_reach(smooth, kCentre, cv::Size(2 * kSize, 2 * kSize), 2.0f);
  EXPECT_EQ(redrawn.at<std::uint8_t>(100, 100), 255) << "the centre, at twice the size";
  EXPECT_EQ(redrawn.at<std::uint8_t>(100, 100 + 2 * 40), 0) << "where the scrap was";
  EXPECT_EQ(redrawn.at<std::uint8_t>(100, 100 - 2 * 25), 255) << "where the notch was";
}

TEST(StarShapedRegion, ACentreOutsideReachesNothing) {
  cv::Mat ring = disc(30);
  cv::circle(ring, cv::Point(50, 50), 10, cv::Scalar(0), cv::FILLED);
  for (const float r : ray_reach(ring, kCentre, 36, 2.0f)) EXPECT_EQ(r, 0.0f);
}

}  // namespace
}  // namespace fw::photo
