#pragma once
// Where on a face the eyes rest while they attend it. People looking at a
// face do not stare at one point: they move between the eyes and the mouth
// in small saccades, a few degrees apart, each fixation lasting some
// hundreds of milliseconds (Yarbus 1967, "Eye Movements and Vision";
// Henderson, Williams & Falk 2005, "Eye movements are functional during
// face learning", Memory & Cognition 33), and look at the mouth more while
// that face speaks (Vatikiotis-Bateson, Eigsti, Yano & Munhall 1998,
// "Eye movement of perceivers during audiovisual speech perception",
// Perception & Psychophysics 60). These small saccades are most of the
// saccades people make in conversation, as in Lee, Badler & Badler's
// recordings ("Eyes Alive", 2002: amplitudes fall off exponentially, most
// under 10 degrees).
#include <cstdint>
#include <optional>
#include <random>

#include <glm/vec3.hpp>

#include "fw/behavior/perception.hpp"

namespace fw::behavior {

enum class FacePoint : std::uint8_t { left_eye, right_eye, nose, mouth };

class FaceScan {
 public:
  /// A fixation on one point of a face (log-normal: median, sigma of log).
  static constexpr double kFixationS = 0.33, kFixationSpread = 0.4;
  static constexpr double kShortestS = 0.25, kLongestS = 2.0;
  /// How often the next point is the mouth, and the nose (the centre of the
  /// face, where many fixations land: Henderson et al. 2005), while the face
  /// speaks and not; the rest go to an eye.
  static constexpr double kMouthWhileSpeaking = 0.3, kMouthOtherwise = 0.05;
  static constexpr double kNose = 0.25;

  explicit FaceScan(std::uint64_t seed);
  /// The point to rest on at `now_s`: a new face starts at an eye.
  FacePoint step(double now_s, std::optional<FaceId> attended, bool attended_speaks);

 private:
  std::mt19937_64 rng_;
  std::optional<FaceId> face_;
  FacePoint point_ = FacePoint::left_eye;
  double until_s_ = 0;
};

/// The point `p` of the face `s` describes, in the room frame: an eye 32 mm
/// to either side of the eyes' midpoint, across the head as it is turned,
/// the mouth, or the nose (a little over halfway from the eyes to the mouth).
glm::vec3 face_point_room(const FaceSnapshot& s, FacePoint p);

}  // namespace fw::behavior
