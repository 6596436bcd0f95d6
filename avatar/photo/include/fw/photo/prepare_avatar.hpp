#pragma once
// Photo -> avatar package: the one entry point of avatar/photo.
//
// Data flow: bytes -> inspection (format, size, completeness) -> decode
// (EXIF upright) -> face detection on a reduced copy -> 68 landmarks at full
// resolution -> checks (size, edges, pose, open eyes) -> alignment by the eye
// centres -> the head's 3D pose and frontal landmarks -> the photo's
// expression estimated and taken out of the landmarks -> face texture
// through the pose (hidden parts from the mirror side), warped to the
// neutral landmarks -> thin-plate fit of the generic mesh -> eye holes, iris
// colour, closed-lid layer -> vascular region masks, skin tone -> encoded
// package.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/image.hpp"
#include "fw/photo/photo_limits.hpp"
#include "fw/photo/prep_error.hpp"

namespace fw::photo {

struct PrepOptions {
  int face_index = 0;      ///< which face, by size: 0 = the largest
  int quality = 80;        ///< WebP quality of the textures, 1..100
  int texture_size = 320;  ///< face texture side in pixels, 128..512 (the frame is 5.4 inter-ocular distances across)
  /// false: no eye layer (the non-masking mode): the face texture keeps the
  /// photo's eyes, which then cannot look around.
  bool eye_layer = true;
};

/// What preparation found, for people and previews.
struct PrepReport {
  int faces_found = 0;
  int face_index = 0;
  int photo_width = 0, photo_height = 0;  ///< upright
  std::array<glm::vec2, 68> photo_landmarks{};  ///< photo pixels, upright
  float inter_ocular_px = 0;
  float roll_deg = 0;  ///< eye-line angle in the photo
  float yaw_deg = 0;   ///< estimated head turn, from the nose against the jaw line (what the pose check uses)
  /// The head's pose fitted in 3D: + yaw turns the nose to the viewer's right, + pitch lifts it.
  float head_yaw_deg = 0, head_pitch_deg = 0;
  /// The photo's own expression as action-unit intensities (codec::kAuChannels
  /// order), taken out of the avatar's texture and fit.
  std::array<float, codec::kAuChannelCount> photo_expression{};
  std::vector<std::string> warnings;
  model::RgbaImage face_texture;  ///< the aligned texture as packaged (with eye holes)
};

struct PreparedAvatar {
  model::AvatarPackage package;
  PrepReport report;
};

class FaceFinder;

/// Holds the loaded landmark model; one per thread (dlib's detector is not
/// thread-safe), reused for every photo.
class AvatarPreparer {
 public:
  /// Loads dlib's 68-point model from `landmark_model` or the default place
  /// (see landmark_model.hpp); nullptr and `error` if it cannot.
  static std::unique_ptr<AvatarPreparer> create(const std::optional<std::filesystem::path>& landmark_model,
                                                PrepError& error);
  ~AvatarPreparer();

  /// Checks what can be checked without the landmark model: the format
  /// signature, the header's size, the byte and pixel limits. A server calls
  /// it first so that a file that is no photo is refused at once, not after
  /// the model has loaded. prepare() runs the same check. `max_pixels`: a
  /// lower pixel limit than kMaxPhotoPixels (a server's own, a flag).
  static bool check_photo(std::span<const std::uint8_t> photo, PrepError& error,
                          std::size_t max_pixels = kMaxPhotoPixels);

  /// Prepares one photo (JPEG, PNG or WebP bytes). nullopt and `error` (with a
  /// message for the person) if the photo cannot make an avatar.
  std::optional<PreparedAvatar> prepare(std::span<const std::uint8_t> photo, const PrepOptions& options,
                                        PrepError& error);

  /// As prepare(), but every texture's colours are sampled from
  /// `colour_source` (the same photo repainted: the same size, upright)
  /// while the face, its fit and the head's matte are all found on `photo`.
  /// What the photo's pixels become is then visible in the package: paint
  /// everything but the head a marker colour, and any marker in a render is
  /// background the matte let through.
  std::optional<PreparedAvatar> prepare(std::span<const std::uint8_t> photo,
                                        std::span<const std::uint8_t> colour_source, const PrepOptions& options,
                                        PrepError& error);

 private:
  explicit AvatarPreparer(std::unique_ptr<FaceFinder> finder);
  std::unique_ptr<FaceFinder> finder_;
};

}  // namespace fw::photo
