// The lobby's residents as compiled in (server/avatars/resident_faces.hpp)
// against their portraits prepared today: a change to the photo pipeline or
// the generic face that moves a resident's fit or repaints its face fails
// here, with the command that prepares them again, instead of leaving the
// lobby wearing faces no upload would get any more (or refusing to start on
// a new generic face). In avatar_repreparation_tests: the landmark model
// loads once per process.
#include "resident_faces.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "file_bytes.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "fw/render/image_codec.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

constexpr const char* kRemake = " (prepare them again: cmake --build build --target remake-residents)";

model::AvatarPackage parsed(std::span<const std::uint8_t> bytes) {
  model::AvatarPackage package;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(bytes, package, error)) << error << kRemake;
  return package;
}

model::RgbaImage decoded(const model::PackageImage& image) {
  model::RgbaImage pixels;
  std::string error;
  EXPECT_TRUE(render::decode_image(image.bytes, 4096, pixels, error)) << error;
  return pixels;
}

/// The largest mean absolute difference of the colour channels over any
/// 8x8 block of two images, 0..255: a change of a small region (a shadow
/// under the jaw) shows, which a mean over the whole texture would drown.
double worst_block_difference(const model::RgbaImage& a, const model::RgbaImage& b) {
  constexpr int kBlock = 8;
  if (a.width != b.width || a.height != b.height) return 255;
  double worst = 0;
  for (int by = 0; by + kBlock <= a.height; by += kBlock)
    for (int bx = 0; bx + kBlock <= a.width; bx += kBlock) {
      double sum = 0;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x)
          for (int c = 0; c < 3; ++c) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
      worst = std::max(worst, sum / (3.0 * kBlock * kBlock));
    }
  return worst;
}

TEST(ResidentFaces, AreTheLobbysThreeEachWithAFaceOfTheirOwn) {
  const auto residents = resident_faces();
  ASSERT_EQ(residents.size(), 3u);
  std::set<std::string_view> names, packages;
  for (const ResidentFace& resident : residents) {
    names.insert(resident.name);
    packages.insert(resident.package);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(resident.package.data());
    const model::AvatarPackage package = parsed({bytes, resident.package.size()});
    EXPECT_EQ(package.generic_face_version, model::generic_face().version) << resident.name << kRemake;
    EXPECT_EQ(package.texture_light, model::TextureLight::photo) << resident.name << ": a photo's lit colours";
  }
  EXPECT_EQ(names.size(), 3u);
  EXPECT_EQ(packages.size(), 3u);
}

TEST(ResidentFaces, AreTheirPortraitsAsPreparedToday) {
  photo::PrepError error;
  const auto preparer = photo::AvatarPreparer::create(std::nullopt, error);
  ASSERT_NE(preparer, nullptr) << error.message;
  for (const ResidentFace& resident : resident_faces()) {
    SCOPED_TRACE(std::string(resident.name));
    const auto photo = test::file_bytes(test::source_path(std::string(resident.portrait)));
    const auto today = preparer->prepare(photo, photo::PrepOptions{}, error);
    ASSERT_TRUE(today) << resident.portrait << ": " << error.message;
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(resident.package.data());
    const model::AvatarPackage shipped = parsed({bytes, resident.package.size()});
    // The same fit: a thousandth of the eye distance allows for OpenCV's
    // and dlib's kernels picked per CPU, far below any change of the fit.
    ASSERT_EQ(shipped.fitted_vertices.size(), today->package.fitted_vertices.size()) << kRemake;
    float worst = 0;
    for (std::size_t i = 0; i < shipped.fitted_vertices.size(); ++i)
      worst = std::max(worst, glm::distance(shipped.fitted_vertices[i], today->package.fitted_vertices[i]));
    EXPECT_LT(worst, 1e-3f) << "the fit moved" << kRemake;
    // The same face texture, but for rounding: 2 levels in any 8x8 block.
    // Averaging the neck's shadow over each texel moved blocks by 4 to 6.
    EXPECT_LT(worst_block_difference(decoded(shipped.face_texture), decoded(today->package.face_texture)), 2.0)
        << "the face texture changed" << kRemake;
  }
}

}  // namespace
}  // namespace fw::server
