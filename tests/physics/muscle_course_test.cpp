// Each person's muscles run their own course (muscle_variation.hpp,
// muscle_course.hpp): deterministic per seed, the reference face at scale
// 0, within the literature's millimetres, always inside the tissue laid for
// them, and two people's faces under one action unit differ in shape while
// each still reads as that unit.
#include "fw/physics/muscle_course.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/muscle_variation.hpp"
#include "fw/physics/tissue_model.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace muscle_course_test {

constexpr float kMm = model::kMillimetresPerUnit;
using test::generic_tissue;

bool same(const CourseShift& a, const CourseShift& b) {
  return a.origin == b.origin && a.insertion == b.insertion && a.bifid_drop == b.bifid_drop;
}

std::size_t pair_of(std::string_view name) { return static_cast<std::size_t>(muscle_index(name, true) / 2); }

TEST(MuscleCourse, ShiftsAreDeterministicWithinTheLiteraturesBoundsAndMirrored) {
  const auto a = muscle_course_shifts(42), b = muscle_course_shifts(42), c = muscle_course_shifts(43);
  bool differs = false;
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    EXPECT_TRUE(same(a[i], b[i])) << muscle_name(i);
    differs = differs || !same(a[i], c[i]);
  }
  EXPECT_TRUE(differs) << "two seeds, two people";
  for (const CourseShift& s : muscle_course_shifts(7, 0.0f)) EXPECT_TRUE(same(s, CourseShift{})) << "scale 0: the reference";

  std::array<glm::vec2, kMusclesPerSide> largest{};
  int bifid_sides = 0, bifid_people = 0, bilateral = 0;
  constexpr int kPeople = 3000;
  for (std::uint64_t seed = 0; seed < kPeople; ++seed) {
    const auto shift = muscle_course_shifts(seed);
    for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
      const CourseSpread spread = course_spread(pair);
      const glm::vec2 bound_o = (1.0f + kSideCourseShare) * spread.origin_mm / kMm + 1e-6f;
      const glm::vec2 bound_i = (1.0f + kSideCourseShare) * spread.insertion_mm / kMm + 1e-6f;
      for (std::size_t side = 0; side < 2; ++side) {
        const CourseShift& s = shift[2 * pair + side];
        ASSERT_LE(std::abs(s.origin.x), bound_o.x) << muscle_name(2 * pair + side);
        ASSERT_LE(std::abs(s.origin.y), bound_o.y) << muscle_name(2 * pair + side);
        ASSERT_LE(std::abs(s.insertion.x), bound_i.x) << muscle_name(2 * pair + side);
        ASSERT_LE(std::abs(s.insertion.y), bound_i.y) << muscle_name(2 * pair + side);
        largest[pair] = glm::max(largest[pair], glm::abs(s.origin));
      }
      // Both sides alike (the right mirrored) but for the sides' own share.
      const CourseShift &left = shift[2 * pair], &right = shift[2 * pair + 1];
      const glm::vec2 asymmetry = 2.0f * kSideCourseShare * spread.origin_mm / kMm + 1e-6f;
      ASSERT_LE(std::abs(left.origin.x + right.origin.x), asymmetry.x) << muscle_name(2 * pair);
      ASSERT_LE(std::abs(left.origin.y - right.origin.y), asymmetry.y) << muscle_name(2 * pair);
    }
    const std::size_t zm = 2 * pair_of("zygomatic_major");
    const int sides = (shift[zm].bifid_drop > 0.0f) + (shift[zm + 1].bifid_drop > 0.0f);
    bifid_sides += sides;
    bifid_people += sides > 0;
    bilateral += sides == 2;
    for (std::size_t i = 0; i < kMuscleCount; ++i)
      if (i / 2 != zm / 2) {
        ASSERT_EQ(shift[i].bifid_drop, 0.0f) << "only the zygomaticus major is found bifid";
      }
  }
  // The range is used, and the sphincters and jaw muscles stay put.
  for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
    const glm::vec2 spread = course_spread(pair).origin_mm / kMm;
    EXPECT_GE(largest[pair].x, 0.9f * spread.x) << facial_muscle_definitions()[pair].name;
    EXPECT_GE(largest[pair].y, 0.9f * spread.y) << facial_muscle_definitions()[pair].name;
  }
  for (std::string_view fixed : {"orbicularis_oris_peripheral", "orbicularis_oculi_orbital", "masseter"}) {
    const CourseSpread s = course_spread(pair_of(fixed));
    EXPECT_EQ(s.origin_mm, glm::vec2(0.0f)) << fixed;
    EXPECT_EQ(s.insertion_mm, glm::vec2(0.0f)) << fixed;
  }
  // Pessa et al. 1998: 34 % of hemifaces bifid; Hu et al. 2008: bilateral
  // in 71 % of those who have one.
  EXPECT_NEAR(bifid_sides / (2.0 * kPeople), kBifidShare, 0.03);
  EXPECT_NEAR(double(bilateral) / bifid_people, 0.714, 0.05);
}

TEST(MuscleCourse, ScaleZeroLaysTheReferenceMusclesExactly) {
  const TissueModel& m = *generic_tissue();
  const MuscleCourse reference = lay_muscle_course(m, muscle_course_shifts(99, 0.0f), true);
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    EXPECT_EQ(reference.origin[i], m.muscles[i].origin) << muscle_name(i);
    EXPECT_FALSE(reference.own[i]) << muscle_name(i) << ": the model's own attachments";
    if (m.muscles[i].kind != MuscleKind::linear) continue;
    const MuscleLine line = muscle_line(m, i, glm::vec2(0.0f), glm::vec2(0.0f));
    EXPECT_EQ(line.origin, m.muscles[i].origin) << muscle_name(i) << ": one place lays the lines";
  }
  EXPECT_TRUE(reference.attach_node.empty());
  EXPECT_FALSE(reference.own_particles);
  const MuscleCourse person = lay_muscle_course(m, muscle_course_shifts(99), true);
  EXPECT_FALSE(person.attach_node.empty());
  EXPECT_TRUE(person.own_particles) << "an XPBD face's particles follow its muscles";
}

// The weighted centre of a muscle's attachments: where it pulls.
glm::vec3 pull_centre(const TissueModel& m, const AttachmentSpan& span) {
  glm::vec3 sum(0.0f);
  float total = 0.0f;
  for (std::uint32_t t = 0; t < span.count; ++t) {
    const std::size_t n = span.node[t];
    sum += span.weight[t] * glm::vec3(m.rest_x[n], m.rest_y[n], m.rest_z[n]);
    total += span.weight[t];
  }
  return sum / total;
}

// A person's muscles keep to their side and to the tissue that takes a
// pull, and pull where their course took them.
TEST(MuscleCourse, EveryPersonsMusclesStayOnTheirSideInTheTissue) {
  const TissueModel& m = *generic_tissue();
  const MuscleCourse reference = lay_muscle_course(m, muscle_course_shifts(0, 0.0f));
  float farthest_mm = 0.0f;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const auto shift = muscle_course_shifts(seed);
    const MuscleCourse course = lay_muscle_course(m, shift);
    for (std::size_t i = 0; i < kMuscleCount; ++i) {
      if (m.muscles[i].kind != MuscleKind::linear) continue;
      const MuscleDefinition& def = facial_muscle_definitions()[i / 2];
      const MuscleLine line = muscle_line(m, i, shift[i].origin, shift[i].insertion);
      const MuscleLine reference_line = muscle_line(m, i, glm::vec2(0.0f), glm::vec2(0.0f));
      for (const glm::vec3& p : {line.origin, line.insertion})
        ASSERT_GT(p.x * reference_line.origin.x, 0.0f) << muscle_name(i) << " crossed the midline, seed " << seed;
      const AttachmentSpan span = muscle_attachments(m, course, i);
      ASSERT_GT(span.count, 0u) << muscle_name(i) << " of seed " << seed << " pulls nothing";
      for (std::uint32_t t = 0; t < span.count; ++t) {
        const std::size_t layer = span.node[t] / m.vertex_count;
        ASSERT_TRUE(layer >= 1 && layer <= 3) << muscle_name(i) << ": dermis, fat and fascia only";
        ASSERT_EQ(span.node[t] % m.vertex_count, span.column[t]);
        ASSERT_TRUE(takes_pull(m, def, span.column[t])) << muscle_name(i) << " pulls a held or nose column";
        ASSERT_GE(span.weight[t], kLeastAttachment);
        ASSERT_LE(span.weight[t], 1.0f);
        ASSERT_GT(m.rest_x[span.node[t]] * reference_line.origin.x, -0.05f) << muscle_name(i) << " pulls the other side";
      }
      farthest_mm = std::max(farthest_mm, glm::distance(pull_centre(m, span), pull_centre(m, muscle_attachments(m, reference, i))) * kMm);
    }
  }
  std::printf("the farthest a person's muscle moved its pull: %.1f mm\n", farthest_mm);
  EXPECT_GT(farthest_mm, 2.0f);
  EXPECT_LT(farthest_mm, 12.0f);
}

// One person's course, the same in every solver: the same face with and
// without its courses (strengths alike) differs, and alike in all three.
TEST(MuscleCourse, EverySolverRunsThePersonsCourse) {
  constexpr std::size_t kSmile = 15;  // AU 12, left
  ASSERT_EQ(codec::kAuChannels[kSmile].au, 12);
  std::array<float, codec::kAuChannelCount> targets{};
  targets[kSmile] = 1.0f;
  targets[static_cast<std::size_t>(codec::au_channel(9, codec::AuSide::both))] = 0.6f;
  std::vector<std::vector<glm::vec3>> change;
  for (const Solver solver : {Solver::projective, Solver::mass_spring, Solver::pbd}) {
    std::array<std::vector<glm::vec3>, 2> surface;
    for (int course = 0; course < 2; ++course) {
      SimulationOptions options;
      options.solver = solver;
      options.seed = 5;
      options.individual_variation = kPersonVariation;
      options.course_variation = static_cast<float>(course);
      FaceSimulation sim(generic_tissue(), options);
      sim.set_action_units(targets);
      for (int f = 0; f < 90; ++f) sim.step(1.0 / 30.0);
      surface[static_cast<std::size_t>(course)] = sim.surface();
    }
    std::vector<glm::vec3> d(surface[0].size());
    double sum = 0.0;
    for (std::size_t v = 0; v < d.size(); ++v) {
      d[v] = (surface[1][v] - surface[0][v]) * kMm;
      sum += glm::dot(d[v], d[v]);
    }
    const double rms = std::sqrt(sum / double(d.size()));
    std::printf("solver %d: the person's courses move the face by %.2f mm RMS\n", static_cast<int>(solver), rms);
    EXPECT_GT(rms, 0.05) << "solver " << static_cast<int>(solver) << " ignores the person's courses";
    change.push_back(std::move(d));
  }
  // The same variation: each solver's change points the projective one's way.
  for (std::size_t k = 1; k < change.size(); ++k) {
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (std::size_t v = 0; v < change[0].size(); ++v) {
      ab += glm::dot(change[0][v], change[k][v]);
      aa += glm::dot(change[0][v], change[0][v]);
      bb += glm::dot(change[k][v], change[k][v]);
    }
    const double cosine = ab / std::sqrt(aa * bb);
    std::printf("solver %zu's change against the projective one's: cosine %.2f\n", k, cosine);
    EXPECT_GT(cosine, 0.7);
  }
}

}  // namespace muscle_course_test
}  // namespace fw::physics
