#pragma once
// One person's muscles as laid on a tissue model: each linear muscle's
// origin and insertion moved by the person's course (muscle_variation.hpp)
// and the nodes it pulls from there, with their weights. The model stays
// the reference face's, shared by every face of it (and with it the
// projective solver's factored matrix, in which no muscle enters: the
// muscles pull on the right-hand side); each face holds only the
// attachments of the muscles its course moved, every solver reading them
// through muscle_attachments().
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/physics/facial_muscles.hpp"
#include "fw/physics/muscle_particles.hpp"
#include "fw/physics/muscle_variation.hpp"

namespace fw::physics {

struct TissueModel;

/// Weights below this are no attachment (a muscle's footprint ends there).
inline constexpr float kLeastAttachment = 0.01f;

/// A linear (or jaw) muscle's action line: its bony origin and the point of
/// the fascia it inserts at, model units.
struct MuscleLine {
  glm::vec3 origin{0.0f};
  glm::vec3 insertion{0.0f};
};

/// A point at face-plane `xy` below the skin of the front-facing column
/// nearest to it, by `share` of that column's thickness plus `extra`.
/// The model's skin, thickness and skull normals must be built.
glm::vec3 point_below_skin(const TissueModel& model, glm::vec2 xy, float share, float extra);

/// The action line of a muscle of `definition` whose anchors lie at
/// face-plane points `origin_xy` and `insertion_xy`: the origin below the
/// skull surface by `origin_depth`, the insertion in the fascia.
MuscleLine lay_muscle_line(const TissueModel& model, const MuscleDefinition& definition, glm::vec2 origin_xy,
                           glm::vec2 insertion_xy);

/// Muscle `index`'s action line (linear or jaw) with its anchors moved by
/// `shift` (face plane, model units): each anchor keeps to its own side of
/// the midline, no nearer to it than half its reference distance.
/// A zero shift gives the reference line.
MuscleLine muscle_line(const TissueModel& model, std::size_t index, glm::vec2 origin_shift, glm::vec2 insertion_shift);

/// How much of a muscle's pull the nodes of `layer` take: most at the
/// fascia, less through the fat into the dermis (the mimetic muscles insert
/// into the skin); none in the epidermis and the bone. A muscle within the
/// red of the lips (MuscleDefinition::within_the_lips) pulls the dermis,
/// fat and fascia alike.
float attached_layer_share(std::size_t layer, bool within_the_lips = false);

/// Linear muscle `definition`'s pull weight on `node` along `line`: the
/// profile of muscle_profile.hpp times the node's layer share (no cut-off).
float linear_attachment_weight(const TissueModel& model, const MuscleDefinition& definition, std::size_t node,
                               const MuscleLine& line);

/// Attachments being laid: appends to one set of arrays (the model's, or
/// a face's own).
struct MuscleAttachments {
  std::vector<std::uint16_t>& node;
  std::vector<float>& weight;
  std::vector<std::uint16_t>& column;
  void add(std::uint16_t n, float w, std::uint32_t v) {
    node.push_back(n);
    weight.push_back(w);
    column.push_back(static_cast<std::uint16_t>(v));
  }
};

/// Whether column `v` takes the pull of a muscle of `definition`: not the
/// held outline (its fascia is pinned: a pull would only fold its skin
/// over the fixed frame), not the nose unless the muscle is the nose's.
bool takes_pull(const TissueModel& model, const MuscleDefinition& definition, std::uint32_t v);

/// Lays a linear muscle along `line` over the dermis, fat and fascia nodes
/// of every column that takes its pull, weight >= kLeastAttachment. With a
/// `lower` line (a bifid zygomaticus major's inferior bundle) each bundle
/// pulls with half the weight.
void lay_linear_attachments(const TissueModel& model, const MuscleDefinition& definition, const MuscleLine& line,
                            const MuscleLine* lower, MuscleAttachments& out);

/// One face's muscles: what the solvers read instead of the model's
/// reference muscles.
struct MuscleCourse {
  /// Rest place of each muscle's origin (a sphincter's centre).
  std::array<glm::vec3, kMuscleCount> origin{};
  /// The muscles this face's course moved lay their own attachments here,
  /// [first, last) each; the others' are the model's.
  std::array<bool, kMuscleCount> own{};
  std::array<std::uint32_t, kMuscleCount> first{}, last{};
  std::vector<std::uint16_t> attach_node, attach_column;
  std::vector<float> attach_weight;
  /// The XPBD solver's particles and ties along this face's muscles (only
  /// for a face stepped by it whose course moved a muscle; else unused).
  MuscleParticles particles;
  bool own_particles = false;

  std::size_t memory_bytes() const;
};

/// One muscle's attachments as a face pulls them.
struct AttachmentSpan {
  const std::uint16_t* node;
  const float* weight;
  const std::uint16_t* column;
  std::uint32_t count;
};
AttachmentSpan muscle_attachments(const TissueModel& model, const MuscleCourse& course, std::size_t muscle);

/// `model`'s muscles laid along the courses `shift`
/// (muscle_course_shifts): each moved linear muscle's origin and its own
/// attachments; all zero shifts give the model's own muscles exactly. A
/// bifid zygomaticus major pulls half along the superior bundle, half along
/// the inferior one inserting `bifid_drop` lower. `xpbd`: also lay the
/// XPBD solver's particles and ties along them.
MuscleCourse lay_muscle_course(const TissueModel& model, const std::array<CourseShift, kMuscleCount>& shift,
                               bool xpbd = false);

}  // namespace fw::physics
