#include "fw/physics/tissue_model.hpp"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "fw/physics/prism_volume.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace {

TEST(TissueModel, IsAtLeastThePapersSize) {
  // The behavioral-animation paper, Table 1: 1078 nodes, 7398 springs, 42 muscles, 1042 elements.
  const TissueModel& m = *test::generic_tissue();
  EXPECT_GE(m.node_count, 1000u);
  EXPECT_GE(m.spring_count(), 7000u);
  EXPECT_GE(m.element_count(), 1000u);
  EXPECT_EQ(m.muscles.size(), kMuscleCount);
  EXPECT_EQ(m.node_count, m.vertex_count * kTissueLayerCount);
}

TEST(TissueModel, EpidermisIsTheSkinAndLayersGoInward) {
  const TissueModel& m = *test::generic_tissue();
  const auto& skin = model::generic_face().skin.positions;
  for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
    EXPECT_EQ(glm::vec3(m.rest_x[v], m.rest_y[v], m.rest_z[v]), skin[v]);
    const std::size_t bone = m.moving_node_count + v;
    const glm::vec3 inward = glm::vec3(m.rest_x[bone], m.rest_y[bone], m.rest_z[bone]) - skin[v];
    EXPECT_LT(glm::dot(inward, m.skull_normal[v]), 0.0f) << v;
    EXPECT_GT(m.column_thickness[v], 0.0f);
  }
}

TEST(TissueModel, EveryElementAndSpringIsSound) {
  const TissueModel& m = *test::generic_tissue();
  for (float v : m.element_rest_volume) EXPECT_GT(v, 0.0f);
  for (float r : m.spring_rest) EXPECT_GT(r, 0.0f);
  for (std::size_t s = 0; s < m.spring_count(); ++s) {
    EXPECT_LT(m.spring_a[s], m.node_count);
    EXPECT_LT(m.spring_b[s], m.node_count);
    EXPECT_FALSE(m.spring_a[s] >= m.moving_node_count && m.spring_b[s] >= m.moving_node_count)
        << "a unit between two bone nodes does nothing";
  }
}

TEST(TissueModel, EveryFaceMuscleIsAttachedAndBothSidesAlike) {
  const TissueModel& m = *test::generic_tissue();
  for (std::size_t i = 0; i < kMuscleCount; i += 2) {
    const TissueMuscle &left = m.muscles[i], &right = m.muscles[i + 1];
    if (left.kind == MuscleKind::jaw) {
      EXPECT_EQ(left.first, left.last);
      continue;
    }
    EXPECT_GT(left.last - left.first, 0u) << muscle_name(i);
    EXPECT_EQ(left.last - left.first, right.last - right.first) << muscle_name(i);
    EXPECT_NEAR(left.origin.x, -right.origin.x, 1e-5f) << muscle_name(i);
  }
}

TEST(TissueModel, TheLowerLipRidesTheJawAndTheBrowDoesNot) {
  const TissueModel& m = *test::generic_tissue();
  const auto& face = model::generic_face();
  EXPECT_FLOAT_EQ(m.jaw_share[face.landmark_vertices[57]], 1.0f) << "lower lip";
  EXPECT_FLOAT_EQ(m.jaw_share[face.landmark_vertices[8]], 1.0f) << "chin";
  EXPECT_FLOAT_EQ(m.jaw_share[face.landmark_vertices[51]], 0.0f) << "upper lip";
  EXPECT_FLOAT_EQ(m.jaw_share[face.landmark_vertices[24]], 0.0f) << "brow";
}

// The largest omega^2 of the mass-spring solver's linearised tissue at rest:
// the top eigenvalue of M^-1 K, K the units at their stiffer slope and the
// prisms' volume stiffness, the held nodes fixed; by power iteration, apart
// from the model's own (Gershgorin) estimate.
double largest_omega2(const TissueModel& m) {
  const std::size_t n = m.node_count;
  auto moves = [&](std::size_t i) { return i < m.moving_node_count && m.inverse_mass[i] > 0.0f; };
  auto rest = [&](std::size_t i) { return glm::vec3(m.rest_x[i], m.rest_y[i], m.rest_z[i]); };
  std::vector<glm::vec3> v(n, glm::vec3(0.0f)), kv(n);
  for (std::size_t i = 0; i < n; ++i)
    if (moves(i)) v[i] = glm::vec3(std::sin(1.0f + i), std::cos(2.0f * i), std::sin(3.0f * i + 0.5f));
  double lambda = 0.0;
  for (int iteration = 0; iteration < 400; ++iteration) {
    std::fill(kv.begin(), kv.end(), glm::vec3(0.0f));
    for (std::size_t s = 0; s < m.spring_count(); ++s) {
      const std::size_t a = m.spring_a[s], b = m.spring_b[s];
      const StressStrainCurve& c = m.material.curves[static_cast<std::size_t>(m.spring_kind[s])];
      const glm::vec3 d = glm::normalize(rest(b) - rest(a));
      const glm::vec3 f = c.stiffness * c.stiff_ratio * glm::dot(d, v[a] - v[b]) * d;
      kv[a] += f;
      kv[b] -= f;
    }
    for (std::size_t e = 0; e < m.element_count(); ++e) {
      const auto nodes = m.element(e);
      PrismNodes p, gradient;
      for (std::size_t k = 0; k < 6; ++k) p[k] = rest(nodes[k]);
      prism_volume(p, &gradient);
      float dv = 0.0f;
      for (std::size_t k = 0; k < 6; ++k) dv += glm::dot(gradient[k], v[nodes[k]]);
      for (std::size_t k = 0; k < 6; ++k)
        kv[nodes[k]] += m.material.volume_stiffness * m.element_force_scale[e] * dv * gradient[k];
    }
    double norm2 = 0.0, before2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      kv[i] = moves(i) ? kv[i] * m.inverse_mass[i] : glm::vec3(0.0f);
      norm2 += glm::dot(kv[i], kv[i]);
      before2 += glm::dot(v[i], v[i]);
    }
    lambda = std::sqrt(norm2 / before2);
    for (std::size_t i = 0; i < n; ++i) v[i] = kv[i] / static_cast<float>(std::sqrt(norm2));
  }
  return lambda;
}

// The sub-step the model states stable for the mass-spring solver must be
// what the plain node masses allow: semi-implicit Euler is stable while
// h omega_max <= 2, and a bound under 0.5 / omega_max would spend sub-steps
// for nothing. omega_max comes from the plain masses here, so a model that
// quietly made its stiff nodes heavier (mass scaling, which once held every
// bound at 1/184 s or longer) states a sub-step these masses cannot take
// and fails: the normal material barely needed it (measured omega_max
// 181/s, sub-step 1/188 s, h omega 0.96), a tissue with eight times the
// muscle layer's and the volumes' stiffness does (mass scaling stated
// 1/184 s there, h omega 2.6; now 1/504 s).
TEST(TissueModel, TheStatedStableSubStepIsWhatThePlainMassesAllow) {
  TissueOptions stiff;
  for (SpringKind kind : {SpringKind::column_muscle, SpringKind::shear_muscle, SpringKind::fascia})
    stiff.material.curves[static_cast<std::size_t>(kind)].stiffness *= 8.0f;
  stiff.material.volume_stiffness *= 8.0f;
  const auto stiff_model = build_tissue_model(model::generic_face(), model::generic_face().action_units, stiff);
  for (const TissueModel* m : {test::generic_tissue().get(), stiff_model.get()}) {
    const double omega = std::sqrt(largest_omega2(*m));
    EXPECT_LE(m->stable_substep_s * omega, 2.0) << "omega_max " << omega << "/s, sub-step " << m->stable_substep_s << " s";
    EXPECT_GE(m->stable_substep_s * omega, 0.5) << "omega_max " << omega << "/s, sub-step " << m->stable_substep_s << " s";
  }
}

TEST(TissueModel, FitsTheMemoryBudget) {
  EXPECT_LT(test::generic_tissue()->memory_bytes(), 256u * 1024u) << "issue 6: at most 256 KB per face";
}

}  // namespace
}  // namespace fw::physics
