#include "fw/physics/tissue_model.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
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

TEST(TissueModel, StepsStablyAtFourSubStepsPerFrame) {
  EXPECT_GE(test::generic_tissue()->stable_substep_s, 1.0f / 300.0f);
}

TEST(TissueModel, FitsTheMemoryBudget) {
  EXPECT_LT(test::generic_tissue()->memory_bytes(), 256u * 1024u) << "issue 6: at most 256 KB per face";
}

}  // namespace
}  // namespace fw::physics
