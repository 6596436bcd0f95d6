#pragma once
// Variants of a test photo made in code (rotated, mirrored, scaled, darker,
// grayscale, padded, ...), each with the exact map from the original's pixel
// positions to its own, so tests can check where landmarks must land.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

namespace fw::test {

struct PhotoVariant {
  std::string name;
  cv::Mat image;                                   ///< BGR
  std::function<glm::vec2(glm::vec2)> transform;  ///< original pixel -> variant pixel
  bool mirrored = false;                           ///< left and right landmarks swap
};

/// The astronaut portrait (tests/data/astronaut.png).
std::string astronaut_path();
cv::Mat load_astronaut();

/// Rotated 15 degrees, mirrored, scaled by 0.5, darkened, grayscale, padded
/// into a large canvas.
std::vector<PhotoVariant> standard_variants(const cv::Mat& original);

/// Rolled far over: rotated 45, 90 and 180 degrees (the photo's corners
/// filled from its edges).
std::vector<PhotoVariant> roll_variants(const cv::Mat& original);

/// The standard variants, each made 1920x1280 (the photo scaled to fill the
/// height and centred on a grey canvas): the benchmark's photos.
std::vector<PhotoVariant> large_variants(const cv::Mat& original);

/// PNG or JPEG bytes of an image.
std::vector<std::uint8_t> encode(const cv::Mat& image, const std::string& extension = ".png");

}  // namespace fw::test
