#include "fw/physics/muscle_particles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "fw/physics/muscle_course.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics {
namespace {

// Particles per linear muscle's action line and per sphincter's ring.
constexpr std::size_t kLineParticles = 8;
constexpr std::size_t kRingParticles = 12;
constexpr float kTwoPi = 6.28318531f;
// A fully active muscle shortens by this share of its length: skeletal
// fibres work over about 60-100 % of their optimal length (Gordon, Huxley &
// Julian 1966, the sarcomere's length-tension curve).
constexpr float kFullShortening = 0.35f;
// A tie never asks for less than this move at full activation (model
// units, 1.3 mm), so that ties beside the origin are not made rigid.
constexpr float kLeastShortening = 0.02f;

glm::vec3 rest_of(const TissueModel& m, std::size_t node) { return {m.rest_x[node], m.rest_y[node], m.rest_z[node]}; }

// Lays the particles and ties of the muscles as `course` pulls (the
// model's own muscles when it is null).
class Layout {
 public:
  Layout(const TissueModel& m, const MuscleCourse* course, MuscleParticles& out) : m_(m), course_(course), out_(out) {}

  void muscle(std::size_t index) {
    span_ = course_ ? muscle_attachments(m_, *course_, index)
                    : AttachmentSpan{m_.attach_node.data() + m_.muscles[index].first,
                                     m_.attach_weight.data() + m_.muscles[index].first,
                                     m_.attach_column.data() + m_.muscles[index].first,
                                     m_.muscles[index].last - m_.muscles[index].first};
    origin_ = course_ ? course_->origin[index] : m_.muscles[index].origin;
    if (span_.count == 0) return;
    first_particle_ = out_.rest.size();
    if (m_.muscles[index].kind == MuscleKind::sphincter) ring(index);
    else line(index);
  }

 private:
  glm::vec3 rest(std::size_t node) const { return rest_of(m_, node); }

  // A particle rides the bone of the nearest attached column.
  void add_particle(std::size_t index, const glm::vec3& p) {
    std::uint16_t column = span_.column[0];
    float best = std::numeric_limits<float>::max();
    for (std::uint32_t t = 0; t < span_.count; ++t) {
      const float d = glm::distance(rest(span_.node[t]), p);
      if (d < best) best = d, column = span_.column[t];
    }
    out_.rest.push_back(p);
    out_.column.push_back(column);
    out_.muscle.push_back(static_cast<std::uint8_t>(index));
  }

  void add_tie(std::size_t particle, float share) {
    out_.tie_first.push_back(static_cast<std::uint16_t>(first_particle_ + particle));
    out_.tie_share.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(share, 0.0f, 1.0f) * 255.0f)));
  }

  // From the origin to the farthest attachment along the line to their
  // weighted centre.
  void line(std::size_t index) {
    glm::vec3 centre(0.0f);
    float total = 0.0f;
    for (std::uint32_t t = 0; t < span_.count; ++t) {
      centre += span_.weight[t] * rest(span_.node[t]);
      total += span_.weight[t];
    }
    const glm::vec3 o = origin_;
    const glm::vec3 dir = glm::normalize(centre / total - o);
    float length = kLeastShortening;  // never 0, even were every attachment behind the origin
    for (std::uint32_t t = 0; t < span_.count; ++t) length = std::max(length, glm::dot(rest(span_.node[t]) - o, dir));
    constexpr float kLast = static_cast<float>(kLineParticles - 1);
    for (std::size_t k = 0; k < kLineParticles; ++k)
      add_particle(index, o + (static_cast<float>(k) / kLast) * length * dir);
    for (std::uint32_t t = 0; t < span_.count; ++t) {
      const float along = std::clamp(glm::dot(rest(span_.node[t]) - o, dir) / length, 0.0f, 1.0f) * kLast;
      const std::size_t a = std::min(static_cast<std::size_t>(along), kLineParticles - 2);
      add_tie(a, along - static_cast<float>(a));
    }
  }

  // One particle per sector of the attachments about the centre (in the
  // face's plane), at their weighted mean.
  void ring(std::size_t index) {
    auto sector = [&](std::uint32_t t) {
      const glm::vec3 d = rest(span_.node[t]) - origin_;
      const float angle = std::atan2(d.y, d.x) + kTwoPi;
      return static_cast<std::size_t>(angle / kTwoPi * kRingParticles) % kRingParticles;
    };
    std::array<glm::vec3, kRingParticles> sum{};
    std::array<float, kRingParticles> weight{};
    for (std::uint32_t t = 0; t < span_.count; ++t) {
      sum[sector(t)] += span_.weight[t] * rest(span_.node[t]);
      weight[sector(t)] += span_.weight[t];
    }
    std::array<std::size_t, kRingParticles> particle{};
    std::size_t count = 0;
    for (std::size_t k = 0; k < kRingParticles; ++k) {
      if (weight[k] <= 0.0f) continue;
      add_particle(index, sum[k] / weight[k]);
      particle[k] = count++;
    }
    for (std::uint32_t t = 0; t < span_.count; ++t) add_tie(particle[sector(t)], 0.0f);
  }

  const TissueModel& m_;
  const MuscleCourse* course_;
  MuscleParticles& out_;
  AttachmentSpan span_{};
  glm::vec3 origin_{0.0f};
  std::size_t first_particle_ = 0;
};

}  // namespace

MuscleParticles build_muscle_particles(const TissueModel& model, const MuscleCourse* course) {
  MuscleParticles out;
  Layout layout(model, course, out);
  for (std::size_t i = 0; i < model.muscles.size(); ++i) layout.muscle(i);
  out.rest.shrink_to_fit();
  out.column.shrink_to_fit();
  out.muscle.shrink_to_fit();
  out.tie_first.shrink_to_fit();
  out.tie_share.shrink_to_fit();
  return out;
}

void full_contraction(const TissueModel& m, const MuscleParticles& mp, const std::array<glm::vec3, kMuscleCount>& origin,
                      std::vector<glm::vec3>& move) {
  move.resize(mp.particle_count());
  for (std::size_t k = 0; k < mp.particle_count(); ++k) {
    const TissueMuscle& muscle = m.muscles[mp.muscle[k]];
    glm::vec3 d = kFullShortening * (origin[mp.muscle[k]] - mp.rest[k]);
    if (muscle.kind == MuscleKind::sphincter) d *= muscle.pull_scale;
    const glm::vec3& normal = m.skull_normal[mp.column[k]];
    move[k] = d - glm::dot(d, normal) * normal;
  }
}

float tie_stiffness_per_strength(const MuscleParticles& mp, const std::vector<glm::vec3>& move, std::size_t tie,
                                 float weight) {
  const std::size_t a = mp.tie_first[tie];
  const float share = mp.tie_share[tie] * (1.0f / 255.0f);
  const glm::vec3 at_tie = share > 0.0f ? (1.0f - share) * move[a] + share * move[a + 1] : move[a];
  return weight / std::max(glm::length(at_tie), kLeastShortening);
}

std::size_t MuscleParticles::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(rest) + bytes(column) + bytes(muscle) + bytes(tie_first) + bytes(tie_share);
}

}  // namespace fw::physics
