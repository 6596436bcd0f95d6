// The face's anatomy: regional tissue depth, the nose in AU 9, the
// masseter's bulge, the jaw's forward glide and the lips' contact.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/regional_thickness.hpp"
#include "generic_tissue.hpp"

namespace fw::physics::anatomy {
namespace {

using model::FaceRegion;
constexpr double kFrame = 1.0 / 30.0;
constexpr float kMm = model::kMillimetresPerUnit;

std::vector<std::set<FaceRegion>> vertex_regions() {
  const auto& face = model::generic_face();
  std::vector<std::set<FaceRegion>> regions(face.skin.positions.size());
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) regions[face.skin.triangles[f][k]].insert(face.triangle_regions[f]);
  return regions;
}

FaceSimulation settled(Solver solver, const std::array<float, codec::kAuChannelCount>& targets) {
  SimulationOptions options;
  options.solver = solver;
  FaceSimulation sim(test::generic_tissue(), options);
  sim.set_action_units(targets);
  for (int f = 0; f < 300 && !sim.at_rest(); ++f) sim.step(kFrame);
  return sim;
}

std::array<float, codec::kAuChannelCount> au_alone(int au) {
  std::array<float, codec::kAuChannelCount> t{};
  t[static_cast<std::size_t>(codec::au_channel(au, codec::AuSide::both))] = 1.0f;
  return t;
}

// Each column inside one region (every triangle around it in that region)
// is as deep as the region's cited depth, or thinner where columns
// converge, never by more than a third; and the thin regions are thin, the
// thick ones thick (De Greef et al. 2006: forehead ~5 mm, nasal dorsum ~3,
// cheeks ~15, lips 12-13, chin ~11).
TEST(Anatomy, TheTissueIsAsDeepAsItsRegion) {
  const TissueModel& m = *test::generic_tissue();
  const auto regions = vertex_regions();
  std::array<double, model::kFaceRegionCount> sum{};
  std::array<int, model::kFaceRegionCount> count{};
  for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
    if (regions[v].size() != 1) continue;
    const FaceRegion r = *regions[v].begin();
    const float cited = regional_thickness_mm(r), mm = m.column_thickness[v] * kMm;
    EXPECT_LE(mm, cited + 1e-3f) << model::kFaceRegionNames[static_cast<std::size_t>(r)] << " vertex " << v;
    EXPECT_GE(mm, 0.66f * cited) << model::kFaceRegionNames[static_cast<std::size_t>(r)] << " vertex " << v;
    sum[static_cast<std::size_t>(r)] += mm;
    ++count[static_cast<std::size_t>(r)];
  }
  auto mean = [&](FaceRegion r) {
    const auto i = static_cast<std::size_t>(r);
    EXPECT_GT(count[i], 0) << model::kFaceRegionNames[i] << " has a column of its own";
    return count[i] > 0 ? sum[i] / count[i] : 0.0;
  };
  EXPECT_NEAR(mean(FaceRegion::forehead), 5.0, 0.5);
  EXPECT_NEAR(mean(FaceRegion::cheek_left), 15.0, 1.5);
  EXPECT_NEAR(mean(FaceRegion::chin), 11.0, 1.0);
  EXPECT_LT(mean(FaceRegion::forehead), 0.5 * mean(FaceRegion::cheek_left));
  // The nose has no column of its own on this mesh (every one touches the
  // cheeks or the lids): its dorsum, the bridge landmarks, is the thinnest.
  const auto& face = model::generic_face();
  for (int l = model::landmarks::kNoseBridgeBegin; l < model::landmarks::kNoseBridgeEnd; ++l)
    EXPECT_LT(m.column_thickness[face.landmark_vertices[static_cast<std::size_t>(l)]] * kMm, 5.0f) << "landmark " << l;
}

// AU 9 (nose wrinkler): the levator labii superioris alaeque nasi lifts the
// alae and the nasalis and procerus gather the nose's sides up toward the
// dorsum. The alae rise by more than 1.5 mm (2.1 measured) and every column
// on the side of the nose by more than 1 mm (1.2-3.1 mm measured; with the
// nose's fascia pinned and the nasalis pulling down from the maxilla, the
// alae rose 0.5 mm and the sides -0.03 to 0.2 mm). What lies away from the nose and the upper
// lip (hairline, jaw, chin, the sides) moves less than 1 mm (0.5 measured:
// the cheeks' pull spreads through the tissue), and the forehead less than
// 2 mm (1.5 measured): the procerus draws the skin between the brows down,
// part of AU 9 in the FACS manual.
TEST(Anatomy, Au9RaisesTheNosesSideTissue) {
  const auto& face = model::generic_face();
  const auto regions = vertex_regions();
  for (Solver solver : {Solver::projective, Solver::mass_spring}) {
    const FaceSimulation sim = settled(solver, au_alone(9));
    const TissueModel& m = sim.model();
    auto rise_mm = [&](std::uint32_t v) { return (sim.node_position(v).y - m.rest_y[v]) * kMm; };
    for (int l : {31, 35})
      EXPECT_GT(rise_mm(face.landmark_vertices[static_cast<std::size_t>(l)]), 1.5f) << "ala, landmark " << l;
    int sides = 0;
    for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
      const glm::vec3 p = face.skin.positions[v];
      if (!regions[v].contains(FaceRegion::nose) || std::abs(p.x) < 0.08f || p.y > -0.15f) continue;
      EXPECT_GT(rise_mm(v), 1.0f) << "side of the nose, vertex " << v;
      ++sides;
    }
    EXPECT_GE(sides, 4);
    float far = 0.0f, forehead = 0.0f;
    for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
      bool away = true;
      for (FaceRegion r : regions[v])
        away = away && (r == FaceRegion::hairline || r == FaceRegion::chin || r == FaceRegion::jaw_left ||
                        r == FaceRegion::jaw_right || r == FaceRegion::side_left || r == FaceRegion::side_right);
      const float moved = glm::length(sim.node_position(v) - face.skin.positions[v]) * kMm;
      if (away) far = std::max(far, moved);
      if (regions[v].size() == 1 && regions[v].contains(FaceRegion::forehead)) forehead = std::max(forehead, moved);
    }
    EXPECT_LT(far, 1.0f) << "AU 9 moves the face away from the nose";
    EXPECT_LT(forehead, 2.0f) << "AU 9 lowers the skin between the brows, no more";
  }
}

// The nasalis alone lifts the side of the nose toward the dorsum: its pull
// no longer works against the levator's lift.
TEST(Anatomy, TheNasalisPullsTheNosesSideUp) {
  const auto& face = model::generic_face();
  std::array<float, kMuscleCount> drive{};
  drive[static_cast<std::size_t>(muscle_index("nasalis", true))] = 1.0f;
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  sim.set_muscle_activations(drive);
  for (int f = 0; f < 300 && !sim.at_rest(); ++f) sim.step(kFrame);
  const std::uint32_t ala = face.landmark_vertices[35];  // the person's left
  const glm::vec3 d = (sim.node_position(ala) - face.skin.positions[ala]) * kMm;
  EXPECT_GT(d.y, 0.3f) << "up";
  EXPECT_LT(d.x, 0.0f) << "and in, toward the dorsum";
}

// The masseter at full activation thickens its belly by up to 2 mm
// (ultrasound: 1.5-2.5 mm, Raadsheer et al. 1996): the skin over it moves
// outward, along the skull's normal more than along the skin. It also
// closes the jaw a little (0.025 rad), which moves both sides alike, so the
// left side's bulge is measured against its mirror image on the right.
TEST(Anatomy, TheMasseterBulgesOutward) {
  const TissueModel& m = *test::generic_tissue();
  const auto& skin = model::generic_face().skin.positions;
  std::vector<std::uint32_t> mirror(skin.size());
  for (std::uint32_t v = 0; v < skin.size(); ++v) {
    float best = 1e9f;
    for (std::uint32_t w = 0; w < skin.size(); ++w) {
      const float d = glm::length(glm::vec3(-skin[w].x, skin[w].y, skin[w].z) - skin[v]);
      if (d < best) best = d, mirror[v] = w;
    }
  }
  float deepest = 0.0f;
  for (float d : m.bulge_depth) deepest = std::max(deepest, d);
  EXPECT_GT(deepest * kMm, 1.2f) << "the belly's peak, sampled at the columns";
  EXPECT_LE(deepest * kMm, 2.0f + 1e-4f) << "the belly's peak";
  std::array<float, kMuscleCount> drive{};
  drive[static_cast<std::size_t>(muscle_index("masseter", true))] = 1.0f;
  for (Solver solver : {Solver::projective, Solver::mass_spring}) {
    SimulationOptions options;
    options.solver = solver;
    FaceSimulation sim(test::generic_tissue(), options);
    sim.set_muscle_activations(drive);
    for (int f = 0; f < 300 && !sim.at_rest(); ++f) sim.step(kFrame);
    int over_belly = 0;
    float peak = 0.0f;
    for (std::uint32_t v = 0; v < m.vertex_count; ++v) {
      const glm::vec3 left = sim.node_position(v) - skin[v];
      const glm::vec3 right = sim.node_position(mirror[v]) - skin[mirror[v]];
      const glm::vec3 d = (left - glm::vec3(-right.x, right.y, right.z)) * kMm;
      const glm::vec3 n = m.skull_normal[v];
      const float out = glm::dot(d, n), along = glm::length(d - out * n);
      if (skin[v].x > 0.0f && m.bulge_depth[v] > 0.5f * deepest) {
        EXPECT_GT(out, 0.6f) << "over the belly, vertex " << v;
        EXPECT_LT(along, out) << "over the belly, vertex " << v;
        peak = std::max(peak, out);
        ++over_belly;
      }
      if (skin[v].x > 0.0f && skin[v].x < 0.4f) {
        EXPECT_LT(glm::length(d), 0.2f) << "mid-face, vertex " << v;
      }
    }
    EXPECT_GE(over_belly, 2);
  }
}

// Rotation first, then rotation and glide: at AU 26 (0.2 rad) the chin's
// bone moves on the hinge's arc; at AU 27 (0.42 rad) it is 8-14 mm forward
// of that arc (the condyles' glide down the eminence, 15 mm at the widest
// opening, Okeson), so its path is not an arc about the hinge.
TEST(Anatomy, TheJawGlidesForwardAsItOpensWide) {
  const auto& face = model::generic_face();
  const std::uint32_t chin = face.landmark_vertices[model::landmarks::kChin];
  for (Solver solver : {Solver::projective, Solver::mass_spring}) {
    for (int au : {26, 27}) {
      const FaceSimulation sim = settled(solver, au_alone(au));
      const TissueModel& m = sim.model();
      const std::size_t bone = m.moving_node_count + chin;
      const glm::vec3 rest(m.rest_x[bone], m.rest_y[bone], m.rest_z[bone]);
      const float a = sim.jaw_angle_rad();
      const glm::vec3 q = rest - m.jaw_hinge;
      const glm::vec3 arc = m.jaw_hinge + glm::vec3(q.x, std::cos(a) * q.y - std::sin(a) * q.z, std::sin(a) * q.y + std::cos(a) * q.z);
      const glm::vec3 off = (sim.node_position(bone) - arc) * kMm;
      const float radius_change = (glm::length(sim.node_position(bone) - m.jaw_hinge) - glm::length(q)) * kMm;
      if (au == 26) {
        EXPECT_LT(glm::length(off), 0.1f) << "AU 26 turns the jaw only";
      } else {
        EXPECT_GT(off.z, 8.0f) << "forward of the arc";
        EXPECT_LT(off.z, 14.0f);
        EXPECT_LT(off.y, 0.0f) << "and down the eminence";
        EXPECT_GT(std::abs(radius_change), 3.0f) << "not an arc about the hinge";
        const glm::vec3 skin_move = (sim.node_position(chin) - face.skin.positions[chin]) * kMm;
        EXPECT_GT(skin_move.z - (arc - rest).z * kMm, 5.0f) << "the chin's skin goes forward with the bone";
      }
    }
  }
}

// The lips meet and do not pass (lip_contact.hpp): pressed together by AU
// 24, tightened by AU 23, in anger, the upper lip's inner edge stays at or
// above the lower one's (without the contact it ended 1.9, 3.6 and 3.5 mm
// below it). The physics-made AU 24 morph keeps them touching too.
TEST(Anatomy, TheLipsMeetAndDoNotPass) {
  const auto& face = model::generic_face();
  const auto gap_mm = [&](const std::vector<glm::vec3>& skin) {
    float least = 1e9f;
    for (int k = 1; k < 4; ++k)
      least = std::min(least, (skin[face.landmark_vertices[model::landmarks::kInnerLipBegin + k]].y -
                               skin[face.landmark_vertices[model::landmarks::kInnerLipEnd - k]].y) * kMm);
    return least;
  };
  for (const Solver solver : {Solver::projective, Solver::mass_spring, Solver::pbd})
    for (const auto& units : std::vector<std::vector<int>>{{24}, {23, 24}, {17, 24}, {4, 5, 7, 23, 24}}) {
      codec::FaceParams p;
      for (const int au : units) p.set_au(au, 1.0f);
      const FaceSimulation sim = settled(solver, p.au);
      EXPECT_GT(gap_mm(sim.surface()), -0.01f) << "solver " << int(solver) << ", AU " << units.front() << " and "
                                               << units.size() - 1 << " more";
    }
  std::vector<glm::vec3> pressed = face.skin.positions;
  const model::Morph& au24 = face.action_units[static_cast<std::size_t>(codec::au_channel(24, codec::AuSide::both))];
  for (std::size_t v = 0; v < pressed.size(); ++v) pressed[v] += au24.vertex_delta[v];
  EXPECT_GT(gap_mm(pressed), -0.05f) << "the AU 24 morph";
}

// The lips close within a syllable: parted 7 mm (AU 25 0.4, AU 26 0.3),
// the lip-sync track's bilabial pose (AU 24, AU 23 0.6, AU 17 0.3) brings
// them within 1 mm of each other in 8 frames (264 ms), stepped as rooms
// step faces. Syllables come 4-5 a second (Greenberg 1999). With the
// marginal orbicularis oris pulling the lip's dermis and fat as weakly as
// the other muscles do (it lies in the red of the lips: muscle_course.cpp)
// they were still 1.8 mm apart then, at one step a frame; now they touch
// (0.3 mm at one step a frame, 0.5 before the solver's bond to the bone).
TEST(Anatomy, TheLipsCloseWithinASyllable) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  const auto gap_mm = [&] {
    float gap = 0.0f;
    for (const auto& pair : sim.model().lip_pairs) gap += sim.node_position(pair[0]).y - sim.node_position(pair[1]).y;
    return gap / float(sim.model().lip_pairs.size()) * kMm;
  };
  codec::FaceParams open, bilabial;
  open.set_au(25, 0.4f);
  open.set_au(26, 0.3f);
  bilabial.set_au(24, 1.0f);
  bilabial.set_au(23, 0.6f);
  bilabial.set_au(17, 0.3f);
  sim.set_action_units(open.au);
  for (int f = 0; f < 30; ++f) sim.step(kFrame);
  ASSERT_GT(gap_mm(), 6.0f) << "parted";
  sim.set_action_units(bilabial.au);
  for (int f = 0; f < 8; ++f) sim.step(kFrame);
  EXPECT_LT(gap_mm(), 1.0f) << "closed within 264 ms";
}

}  // namespace
}  // namespace fw::physics::anatomy
