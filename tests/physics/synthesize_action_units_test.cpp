#include "fw/physics/synthesize_action_units.hpp"

#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/face_asset.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_pool.hpp"
#include "test_paths.hpp"

namespace fw::physics {
namespace {

model::GenericFace committed_face() {
  std::ifstream in(fw::test::source_path("avatar/model/assets/generic_face.json"), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  model::GenericFace face;
  std::string error;
  EXPECT_TRUE(model::parse_face_asset(text.str(), face, error)) << error;
  return face;
}

// The committed basis is what the physics face makes now. After changing the
// tissue, the muscles or the AU table, run `make facegen` and commit the asset.
TEST(SynthesizeActionUnits, MatchesTheCommittedBasis) {
  const model::GenericFace face = committed_face();
  FacePool pool;
  const BasisSynthesisOptions options;
  const auto synthesized = synthesize_action_units(face, options, &pool);
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const auto& committed = face.action_units[c].vertex_delta;
    ASSERT_EQ(committed.size(), synthesized[c].size());
    float worst = 0.0f;
    for (std::size_t v = 0; v < committed.size(); ++v) worst = std::max(worst, glm::length(committed[v] - synthesized[c][v]));
    // The file keeps 6 digits and writes displacements under the threshold
    // as zero; a value on the threshold may fall either way.
    EXPECT_LE(worst, options.zero_below + 1e-5f)
        << "AU " << int(codec::kAuChannels[c].au) << " channel " << c << " differs by " << worst * model::kMillimetresPerUnit
        << " mm: run `make facegen` and commit avatar/model/assets/generic_face.json";
  }
}

TEST(SynthesizeActionUnits, ReplacesOnlyTheVertexFields) {
  model::GenericFace face = committed_face();
  const auto before = face.action_units;
  std::array<std::vector<glm::vec3>, codec::kAuChannelCount> fields;
  for (auto& f : fields) f.assign(face.skin.positions.size(), glm::vec3(0.001f, 0.0f, 0.0f));
  replace_action_unit_displacements(face, fields);
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    EXPECT_EQ(face.action_units[c].vertex_delta, fields[c]);
    EXPECT_EQ(face.action_units[c].uv_delta, before[c].uv_delta) << "the texture slides stay";
  }
}

TEST(SynthesizeActionUnits, MoveTheSkinWhereTheUnitActs) {
  const model::GenericFace& face = committed_face();
  auto moved_mm = [&](int au, codec::AuSide side, int landmark) {
    const auto& delta = face.action_units[static_cast<std::size_t>(codec::au_channel(au, side))].vertex_delta;
    return glm::length(delta[face.landmark_vertices[static_cast<std::size_t>(landmark)]]) * model::kMillimetresPerUnit;
  };
  EXPECT_GT(moved_mm(12, codec::AuSide::left, model::landmarks::kMouthCornerLeft), 4.0f);
  EXPECT_LT(moved_mm(12, codec::AuSide::left, model::landmarks::kMouthCornerRight), 2.0f) << "the lips pass a little on";
  EXPECT_GT(moved_mm(1, codec::AuSide::right, 21), 1.5f) << "inner brow";
  const auto& up = face.action_units[static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left))].vertex_delta;
  EXPECT_GT(up[face.landmark_vertices[model::landmarks::kMouthCornerLeft]].y, 0.0f) << "AU 12 raises the corner";
}

}  // namespace
}  // namespace fw::physics
