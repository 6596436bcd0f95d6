#pragma once
// The eyeball texture (the package's `eye` member) from the person's own
// eyes: their iris and their white, or the procedural eye when the photo's
// eyes cannot give them.
#include <array>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

struct EyeTexture {
  cv::Mat image;                        ///< BGR, in the EyeLayer mapping
  std::array<std::uint8_t, 3> iris{};   ///< sRGB: the iris's mean colour, or the sampled one on fallback
  bool from_photo = false;
  std::string warning;                  ///< why the procedural eye was used, empty otherwise
};

/// The better-seen of the two eyes (more iris visible, more contrast) gives
/// the iris and the white for both; the iris is as large, and sits as high
/// behind the lids at rest, as in the photo (FORMAT.md, "The eye"). `sampled_iris` colours the procedural
/// eye used when neither eye's iris is found.
EyeTexture make_eye_texture_from_photo(const cv::Mat& photo, const Alignment& alignment, const ModelLandmarks& landmarks,
                                       const model::EyeLayer& eye, std::array<std::uint8_t, 3> sampled_iris, int size);

}  // namespace fw::photo
