#pragma once
// What the tests that look at a committed portrait's avatar as an
// independent observer does share: each portrait prepared as a server
// would, and dlib's 68 points on its neutral render in the head pose the
// photo showed, each made once per test process (a preparation and a
// reading cost about a second each, several under the sanitizers, and the
// likeness and rest tests read the same renders).
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/vec2.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "photo_variants.hpp"
#include "rendered_avatar.hpp"
#include "shared_preparer.hpp"
#include "test_paths.hpp"

namespace fw::photo::neutral_readings {

using Landmarks = std::array<glm::vec2, model::kLandmarkCount>;
inline constexpr float kRadiansPerDegree = 3.14159265f / 180.0f;

/// The sizes (px, square) at which the tests read each neutral render:
/// dlib's points move by a pixel or two with the size (its detector's box
/// and its shape regression see the whole picture), as much as some changes
/// being measured, so a measure pools them.
inline constexpr std::array<int, 7> kRenderSizes = {416, 448, 480, 512, 544, 576, 608};

/// The committed portraits of tests/data.
inline constexpr std::array<const char*, 3> kPortraits = {"astronaut.png", "grace_hopper.jpg",
                                                          "kphotoalbum_jesper.jpg"};

/// tests/data's `photo` prepared as a server would; throws with the reason
/// if it cannot be.
inline const PreparedAvatar& prepared_portrait(const std::string& photo) {
  static std::map<std::string, PreparedAvatar> prepared;
  if (const auto found = prepared.find(photo); found != prepared.end()) return found->second;
  const cv::Mat image = cv::imread(test::test_photo(photo), cv::IMREAD_COLOR);
  if (image.empty()) throw std::runtime_error(photo + " does not load");
  PrepError error;
  auto avatar = test::shared_preparer().prepare(test::encode(image), {}, error);
  if (!avatar) throw std::runtime_error(photo + " is not prepared: " + error.message);
  return prepared.emplace(photo, std::move(*avatar)).first->second;
}

/// The neutral face turned and tilted as the photo's head was: a similarity
/// cannot undo a turn or a tilt, so a frontal render of a photo taken from a
/// little above would differ from it by the pose, not by the person.
inline codec::FaceParams as_photographed(const PrepReport& report) {
  codec::FaceParams params;
  params.head_yaw_rad = report.head_yaw_deg * kRadiansPerDegree;
  params.head_pitch_rad = report.head_pitch_deg * kRadiansPerDegree;
  return params;
}

/// dlib's landmarks on the neutral render (`size` px square) of `photo`'s
/// avatar at the photo's pose; throws if dlib finds no face there.
inline const Landmarks& seen_at_rest(const std::string& photo, int size) {
  static std::map<std::pair<std::string, int>, Landmarks> seen;
  const auto key = std::make_pair(photo, size);
  if (const auto found = seen.find(key); found != seen.end()) return found->second;
  const PreparedAvatar& avatar = prepared_portrait(photo);
  test::RenderedAvatar rendered(avatar.package, size, {0.5f, 0.5f, 0.5f});
  PrepError error;
  const auto read = test::shared_preparer().prepare(
      test::encode(test::to_bgr(rendered.draw(as_photographed(avatar.report)))), {}, error);
  if (!read)
    throw std::runtime_error("dlib finds no face on " + photo + "'s neutral avatar (" + std::to_string(size) +
                             " px): " + error.message);
  return seen.emplace(key, read->report.photo_landmarks).first->second;
}

}  // namespace fw::photo::neutral_readings
