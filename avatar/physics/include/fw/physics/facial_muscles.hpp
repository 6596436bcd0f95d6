#pragma once
// The 42 muscles of facial expression: 21 on each side, defined once for the
// person's left side on the landmarks of the face they are laid on, so they
// follow any fitted face; the right side is the mirror image. The table and
// the reasoning behind each entry live in facial_muscles.cpp and README.md.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fw::physics {

enum class MuscleKind : std::uint8_t {
  linear,     ///< pulls tissue toward a bony origin (Waters' vector muscle)
  sphincter,  ///< pulls tissue toward the centre of an ellipse
  jaw,        ///< turns the jaw; no skin attachment (its belly may bulge: bulge_mm)
};

/// A point on the face: a landmark (or the midpoint of two) plus an offset in
/// the face plane, in model units, for the person's left side. A landmark
/// of -1 makes the offset an absolute model-frame point.
struct FaceAnchor {
  int landmark = -1;
  int landmark2 = -1;
  glm::vec2 offset{0.0f};
};

struct MuscleDefinition {
  std::string_view name;
  MuscleKind kind = MuscleKind::linear;
  float strength = 1.0f;        ///< force at activation 1 on a node of weight 1
  /// Linear muscles: the origin on the bone (depth below the skin surface is
  /// the tissue thickness plus origin_depth) and the insertion in the tissue.
  FaceAnchor origin;
  float origin_depth = 0.0f;    ///< model units below the skull surface
  bool origin_on_jaw = false;   ///< the origin moves with the mandible
  FaceAnchor insertion;
  float width = 0.15f;          ///< lateral radius of the pull
  float reach = 0.08f;          ///< how far beyond the insertion it fades
  float onset = 0.35f;          ///< fraction of the muscle near the origin that does not pull
  /// Sphincters: centre, semi-axes and ring half-width (in units of the
  /// elliptical radius), how the pull toward the centre is weighted per axis
  /// (x, y, z), and how much of the pull the upper half gets.
  FaceAnchor centre;
  glm::vec2 semi_axes{0.3f, 0.2f};
  float ring = 0.5f;
  glm::vec3 pull_scale{1.0f, 1.0f, 0.0f};
  float upper_share = 1.0f;
  /// Sphincters split at the midline (orbicularis oris): each side pulls
  /// only its own half.
  bool half = false;
  /// Jaw muscles: the jaw angle this muscle alone holds at activation 1
  /// (positive opens).
  float jaw_angle_rad = 0.0f;
  /// How much thicker the muscle's belly (between origin and insertion,
  /// `width` to either side) is at activation 1, mm: a contracting muscle
  /// keeps its volume, so it bulges as it shortens. The belly lies in the
  /// muscle layer, under the fascia: the tissue over it is pushed outward.
  float bulge_mm = 0.0f;
  /// The nose's own muscles insert into its skin; the others (the
  /// orbicularis oculi, the lip elevators) end at its border and leave its
  /// columns alone.
  bool moves_nose = false;
  /// The orbicularis oris' marginal part lies within the red of the lips,
  /// with no fat between it and their skin, into which its fibres insert:
  /// it pulls the lip's dermis and fat as fully as its fascia
  /// (muscle_course.hpp, attached_layer_share).
  bool within_the_lips = false;
};

inline constexpr std::size_t kMusclesPerSide = 21;
inline constexpr std::size_t kMuscleCount = 2 * kMusclesPerSide;

/// The left-side definitions; muscle i of the left side has index 2i, its
/// right-side mirror 2i + 1.
const std::array<MuscleDefinition, kMusclesPerSide>& facial_muscle_definitions();

/// The index of muscle `name` on the person's `left` (or right) side, or -1.
int muscle_index(std::string_view name, bool left);

/// "zygomatic_major_left" etc.
std::string muscle_name(std::size_t index);

}  // namespace fw::physics
