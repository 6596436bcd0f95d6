#include "fw/physics/muscle_particles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

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

class Layout {
 public:
  Layout(const TissueModel& m, MuscleParticles& out) : m_(m), out_(out) {}

  void muscle(std::size_t index) {
    const TissueMuscle& muscle = m_.muscles[index];
    if (muscle.first == muscle.last) return;
    first_particle_ = out_.rest.size();
    if (muscle.kind == MuscleKind::sphincter) ring(index, muscle);
    else line(index, muscle);
  }

 private:
  glm::vec3 rest(std::size_t node) const { return rest_of(m_, node); }

  // A particle rides the bone of the nearest attached column.
  void add_particle(std::size_t index, const glm::vec3& p) {
    const TissueMuscle& muscle = m_.muscles[index];
    std::uint16_t column = m_.attach_column[muscle.first];
    float best = std::numeric_limits<float>::max();
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t) {
      const float d = glm::distance(rest(m_.attach_node[t]), p);
      if (d < best) best = d, column = m_.attach_column[t];
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
  void line(std::size_t index, const TissueMuscle& muscle) {
    glm::vec3 centre(0.0f);
    float total = 0.0f;
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t) {
      centre += m_.attach_weight[t] * rest(m_.attach_node[t]);
      total += m_.attach_weight[t];
    }
    const glm::vec3 o = muscle.origin;
    const glm::vec3 dir = glm::normalize(centre / total - o);
    float length = kLeastShortening;  // never 0, even were every attachment behind the origin
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t)
      length = std::max(length, glm::dot(rest(m_.attach_node[t]) - o, dir));
    constexpr float kLast = static_cast<float>(kLineParticles - 1);
    for (std::size_t k = 0; k < kLineParticles; ++k)
      add_particle(index, o + (static_cast<float>(k) / kLast) * length * dir);
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t) {
      const float along = std::clamp(glm::dot(rest(m_.attach_node[t]) - o, dir) / length, 0.0f, 1.0f) * kLast;
      const std::size_t a = std::min(static_cast<std::size_t>(along), kLineParticles - 2);
      add_tie(a, along - static_cast<float>(a));
    }
  }

  // One particle per sector of the attachments about the centre (in the
  // face's plane), at their weighted mean.
  void ring(std::size_t index, const TissueMuscle& muscle) {
    auto sector = [&](std::uint32_t t) {
      const glm::vec3 d = rest(m_.attach_node[t]) - muscle.origin;
      const float angle = std::atan2(d.y, d.x) + kTwoPi;
      return static_cast<std::size_t>(angle / kTwoPi * kRingParticles) % kRingParticles;
    };
    std::array<glm::vec3, kRingParticles> sum{};
    std::array<float, kRingParticles> weight{};
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t) {
      sum[sector(t)] += m_.attach_weight[t] * rest(m_.attach_node[t]);
      weight[sector(t)] += m_.attach_weight[t];
    }
    std::array<std::size_t, kRingParticles> particle{};
    std::size_t count = 0;
    for (std::size_t k = 0; k < kRingParticles; ++k) {
      if (weight[k] <= 0.0f) continue;
      add_particle(index, sum[k] / weight[k]);
      particle[k] = count++;
    }
    for (std::uint32_t t = muscle.first; t < muscle.last; ++t) add_tie(particle[sector(t)], 0.0f);
  }

  const TissueModel& m_;
  MuscleParticles& out_;
  std::size_t first_particle_ = 0;
};

}  // namespace

MuscleParticles build_muscle_particles(const TissueModel& model) {
  MuscleParticles out;
  Layout layout(model, out);
  for (std::size_t i = 0; i < model.muscles.size(); ++i) layout.muscle(i);
  out.rest.shrink_to_fit();
  out.column.shrink_to_fit();
  out.muscle.shrink_to_fit();
  out.tie_first.shrink_to_fit();
  out.tie_share.shrink_to_fit();
  return out;
}

void full_contraction(const TissueModel& m, std::vector<glm::vec3>& move) {
  const MuscleParticles& mp = m.muscle_particles;
  move.resize(mp.particle_count());
  for (std::size_t k = 0; k < mp.particle_count(); ++k) {
    const TissueMuscle& muscle = m.muscles[mp.muscle[k]];
    glm::vec3 d = kFullShortening * (muscle.origin - mp.rest[k]);
    if (muscle.kind == MuscleKind::sphincter) d *= muscle.pull_scale;
    const glm::vec3& normal = m.skull_normal[mp.column[k]];
    move[k] = d - glm::dot(d, normal) * normal;
  }
}

float tie_stiffness_per_strength(const TissueModel& m, const std::vector<glm::vec3>& move, std::size_t tie) {
  const MuscleParticles& mp = m.muscle_particles;
  const std::size_t a = mp.tie_first[tie];
  const float share = mp.tie_share[tie] * (1.0f / 255.0f);
  const glm::vec3 at_tie = share > 0.0f ? (1.0f - share) * move[a] + share * move[a + 1] : move[a];
  return m.attach_weight[tie] / std::max(glm::length(at_tie), kLeastShortening);
}

std::size_t MuscleParticles::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(rest) + bytes(column) + bytes(muscle) + bytes(tie_first) + bytes(tie_share);
}

}  // namespace fw::physics
