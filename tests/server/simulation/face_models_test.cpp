// Every avatar's face model (face_models.hpp), built once per package
// version and kept within a bound, from real packages: the residents'
// (fitted to their portraits) and the procedural demo faces.
#include "face_models.hpp"

#include <cmath>
#include <memory>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "demo_faces.hpp"
#include "face_model.hpp"
#include "resident_faces.hpp"

namespace fw::server {
namespace {

std::span<const std::uint8_t> bytes_of(const ResidentFace& resident) {
  return {reinterpret_cast<const std::uint8_t*>(resident.package.data()), resident.package.size()};
}

TEST(FaceModels, APackageVersionIsBuiltOnceAndFoundAfter) {
  FaceModels models;
  const auto& resident = resident_faces()[0];
  EXPECT_EQ(models.find("v0"), nullptr);
  std::string error;
  const auto first = models.build("v0", bytes_of(resident), error);
  ASSERT_TRUE(first) << error;
  const auto again = models.build("v0", bytes_of(resident), error);
  EXPECT_EQ(again, first);
  EXPECT_EQ(models.find("v0"), first);
  EXPECT_EQ(models.builds(), 1u);
  // The avatar's own fit: its tissue model shares the generic face's factorisation.
  ASSERT_TRUE(first->tissue);
  EXPECT_TRUE(first->tissue->projective_reference);
  EXPECT_EQ(first->tissue->vertex_count, first->avatar.face.skin.positions.size());
}

TEST(FaceModels, TwoPeopleHaveTwoRestShapes) {
  FaceModels models;
  std::string error;
  ASSERT_GE(resident_faces().size(), 2u);
  const auto a = models.build("a", bytes_of(resident_faces()[0]), error);
  const auto b = models.build("b", bytes_of(resident_faces()[1]), error);
  ASSERT_TRUE(a && b) << error;
  double apart = 0.0;
  for (std::size_t v = 0; v < a->tissue->vertex_count; ++v)
    apart = std::max(apart, double(std::abs(a->tissue->rest_x[v] - b->tissue->rest_x[v])));
  EXPECT_GT(apart, 1e-3) << "the residents' fits differ";
}

TEST(FaceModels, ARefusedPackageBuildsNothingAndSaysWhy) {
  FaceModels models;
  std::string error;
  const std::vector<std::uint8_t> junk(100, 7);
  EXPECT_EQ(models.build("junk", junk, error), nullptr);
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(models.size(), 0u);
}

TEST(FaceModels, KeepsAtMostItsBoundOfUnusedModelsAndNeverDropsOneInUse) {
  FaceModels models(2);
  std::string error;
  std::vector<std::vector<std::uint8_t>> packages;
  for (std::uint32_t i = 0; i < 4; ++i) packages.push_back(make_demo_package(i));
  // Held by a room: kept whatever the bound.
  const auto held = models.build("p0", packages[0], error);
  ASSERT_TRUE(held) << error;
  for (std::uint32_t i = 1; i < 4; ++i) ASSERT_TRUE(models.build("p" + std::to_string(i), packages[i], error)) << error;
  EXPECT_EQ(models.size(), 2u);
  EXPECT_EQ(models.find("p0"), held);
  EXPECT_TRUE(models.find("p3")) << "the newest stays";
  EXPECT_FALSE(models.find("p1")) << "the least recently asked for, unused, went first";
  EXPECT_FALSE(models.find("p2"));
  // Built again when asked for again.
  const auto builds = models.builds();
  ASSERT_TRUE(models.build("p1", packages[1], error));
  EXPECT_EQ(models.builds(), builds + 1);
  EXPECT_EQ(models.size(), 2u);
}

}  // namespace
}  // namespace fw::server
