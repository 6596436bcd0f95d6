#include "fw/physics/muscle_course.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "fw/physics/muscle_profile.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics {
namespace {

glm::vec3 node_rest(const TissueModel& m, std::size_t node) { return {m.rest_x[node], m.rest_y[node], m.rest_z[node]}; }

// The front-facing column nearest to `xy` in the face plane.
std::uint32_t nearest_front_column(const TissueModel& m, glm::vec2 xy) {
  std::uint32_t best = 0;
  float best_d = std::numeric_limits<float>::max();
  for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
    if (m.skull_normal[v].z < 0.3f) continue;
    const float d = glm::length(glm::vec2(m.rest_x[v], m.rest_y[v]) - xy);
    // Ties go to the column farther from the midline, so that the two
    // sides of a symmetric face pick mirrored columns.
    const bool tie = std::abs(d - best_d) < 1e-6f;
    if ((!tie && d < best_d) || (tie && std::abs(m.rest_x[v]) > std::abs(m.rest_x[best]))) best_d = d, best = v;
  }
  return best;
}

// A moved anchor keeps to its side of the midline, no nearer to it than
// half its reference distance: a muscle of one side never crosses over.
glm::vec2 on_its_side(glm::vec2 reference, glm::vec2 shift) {
  glm::vec2 p = reference + shift;
  const float side = reference.x < 0.0f ? -1.0f : 1.0f;
  p.x = side * std::max(side * p.x, 0.5f * side * reference.x);
  return p;
}

bool unmoved(const CourseShift& s) { return s.origin == glm::vec2(0.0f) && s.insertion == glm::vec2(0.0f) && s.bifid_drop == 0.0f; }

}  // namespace

glm::vec3 point_below_skin(const TissueModel& m, glm::vec2 xy, float share, float extra) {
  const std::uint32_t v = nearest_front_column(m, xy);
  const glm::vec3 surface(xy, m.rest_z[v]);
  return surface - m.skull_normal[v] * (m.column_thickness[v] * share + extra);
}

MuscleLine lay_muscle_line(const TissueModel& m, const MuscleDefinition& def, glm::vec2 origin_xy,
                           glm::vec2 insertion_xy) {
  return {point_below_skin(m, origin_xy, 1.0f, def.origin_depth),
          point_below_skin(m, insertion_xy, m.layer_depth[static_cast<std::size_t>(TissueLayer::fascia)], 0.0f)};
}

MuscleLine muscle_line(const TissueModel& m, std::size_t index, glm::vec2 origin_shift, glm::vec2 insertion_shift) {
  const TissueMuscle& muscle = m.muscles[index];
  return lay_muscle_line(m, facial_muscle_definitions()[index / 2], on_its_side(muscle.origin_anchor, origin_shift),
                         on_its_side(muscle.insertion_anchor, insertion_shift));
}

float attached_layer_share(std::size_t layer, bool within_the_lips) {
  // The red of the lips is skin over the orbicularis oris' marginal part
  // with no fat between, its fibres inserting into the skin and mucosa
  // (Standring, Gray's Anatomy, 41st ed., 2016, "Lips"): its pull does not
  // thin out on the way to the surface. With the generic shares the
  // bilabial pose took about 300 ms to close the lips from 7 mm apart, more
  // than a syllable; now about 190 ms (tests/physics anatomy_test.cpp).
  const auto kind = static_cast<TissueLayer>(layer);
  if (within_the_lips && (kind == TissueLayer::dermis || kind == TissueLayer::fat)) return 1.0f;
  switch (kind) {
    case TissueLayer::dermis: return 0.3f;
    case TissueLayer::fat: return 0.6f;
    case TissueLayer::fascia: return 1.0f;
    default: return 0.0f;
  }
}

float linear_attachment_weight(const TissueModel& m, const MuscleDefinition& def, std::size_t node,
                               const MuscleLine& line) {
  return linear_muscle_weight(node_rest(m, node), line.origin, line.insertion, def.width, def.reach, def.onset) *
         attached_layer_share(node / m.vertex_count);
}

bool takes_pull(const TissueModel& m, const MuscleDefinition& def, std::uint32_t v) {
  const std::size_t fascia = static_cast<std::size_t>(TissueLayer::fascia) * m.vertex_count + v;
  return m.inverse_mass[fascia] != 0.0f && (!m.column_in_nose[v] || def.moves_nose);
}

void lay_linear_attachments(const TissueModel& m, const MuscleDefinition& def, const MuscleLine& line,
                            const MuscleLine* lower, MuscleAttachments& out) {
  for (std::size_t layer = 1; layer < kMovingLayerCount; ++layer)
    for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
      if (!takes_pull(m, def, v)) continue;
      const auto node = static_cast<std::uint16_t>(layer * m.vertex_count + v);
      float w = linear_attachment_weight(m, def, node, line);
      if (lower) w = 0.5f * (w + linear_attachment_weight(m, def, node, *lower));
      if (w >= kLeastAttachment) out.add(node, w, v);
    }
}

AttachmentSpan muscle_attachments(const TissueModel& m, const MuscleCourse& course, std::size_t i) {
  if (course.own[i])
    return {course.attach_node.data() + course.first[i], course.attach_weight.data() + course.first[i],
            course.attach_column.data() + course.first[i], course.last[i] - course.first[i]};
  const TissueMuscle& muscle = m.muscles[i];
  return {m.attach_node.data() + muscle.first, m.attach_weight.data() + muscle.first,
          m.attach_column.data() + muscle.first, muscle.last - muscle.first};
}

std::size_t MuscleCourse::memory_bytes() const {
  return sizeof(*this) + (attach_node.capacity() + attach_column.capacity()) * sizeof(std::uint16_t) +
         attach_weight.capacity() * sizeof(float) + (own_particles ? particles.memory_bytes() : 0);
}

MuscleCourse lay_muscle_course(const TissueModel& m, const std::array<CourseShift, kMuscleCount>& shift, bool xpbd) {
  MuscleCourse course;
  MuscleAttachments own{course.attach_node, course.attach_weight, course.attach_column};
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    course.origin[i] = m.muscles[i].origin;
    if (m.muscles[i].kind != MuscleKind::linear || unmoved(shift[i])) continue;
    const CourseShift& s = shift[i];
    const MuscleLine line = muscle_line(m, i, s.origin, s.insertion);
    // A bifid muscle's inferior bundle, from the same origin.
    const MuscleLine lower = muscle_line(m, i, s.origin, s.insertion - glm::vec2(0.0f, s.bifid_drop));
    course.origin[i] = line.origin;
    course.own[i] = true;
    course.first[i] = static_cast<std::uint32_t>(course.attach_node.size());
    lay_linear_attachments(m, facial_muscle_definitions()[i / 2], line, s.bifid_drop > 0.0f ? &lower : nullptr, own);
    course.last[i] = static_cast<std::uint32_t>(course.attach_node.size());
  }
  course.attach_node.shrink_to_fit();
  course.attach_weight.shrink_to_fit();
  course.attach_column.shrink_to_fit();
  course.own_particles = xpbd && std::find(course.own.begin(), course.own.end(), true) != course.own.end();
  if (course.own_particles) course.particles = build_muscle_particles(m, &course);
  return course;
}

}  // namespace fw::physics
