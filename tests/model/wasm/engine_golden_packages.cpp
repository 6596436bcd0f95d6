#include "engine_golden_packages.hpp"

#include <cmath>
#include <stdexcept>

#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::test {
namespace {

using model::AvatarPackage;

AvatarPackage parsed(const std::vector<std::uint8_t>& bytes) {
  AvatarPackage package;
  std::string error;
  if (!model::parse_avatar_package(bytes, package, error)) throw std::runtime_error("the seed package: " + error);
  return package;
}

// A fit unlike the photo's: wider below the eyes, a longer face, a slight
// tilt; no eye layer (non-masking mode), the generic head outline and
// albedo textures (a procedural face's).
AvatarPackage synthetic_package(const AvatarPackage& seed) {
  AvatarPackage p = seed;
  const model::GenericFace& generic = model::generic_face();
  p.fitted_vertices.clear();
  for (const glm::vec3& v : generic.skin.positions) {
    const float widen = v.y < 0 ? 1.0f - 0.06f * v.y : 1.0f;
    p.fitted_vertices.emplace_back(v.x * widen + 0.02f * v.y, v.y * 1.07f - 0.01f * v.x);
  }
  for (std::size_t i = 0; i < p.landmarks.size(); ++i)
    p.landmarks[i] = p.fitted_vertices[generic.landmark_vertices[i]];
  p.head_outline.clear();
  p.eye = {};
  p.skin_tone = {200, 150, 120};
  p.iris_colour = {40, 90, 60};
  p.texture_light = model::TextureLight::albedo;
  return p;
}

GoldenPackage refused(std::string name, std::vector<std::uint8_t> bytes) {
  GoldenPackage g{std::move(name), std::move(bytes), false, {}, 0};
  AvatarPackage ignored;
  model::PackageRefusal why = model::PackageRefusal::damaged;
  if (model::parse_avatar_package(g.bytes, ignored, g.error, why))
    throw std::runtime_error("the damaged package " + g.name + " was accepted");
  g.refusal = static_cast<int>(why);
  return g;
}

}  // namespace

std::vector<GoldenPackage> golden_packages(const std::vector<std::uint8_t>& seed) {
  const AvatarPackage photo = parsed(seed);
  std::vector<GoldenPackage> out;
  out.push_back({"photo", seed, true, {}, 0});
  out.push_back({"synthetic", model::serialize_avatar_package(synthetic_package(photo)), true, {}, 0});

  auto bytes = seed;
  bytes.resize(bytes.size() - 10);
  out.push_back(refused("truncated", bytes));
  bytes = seed;
  bytes[0] = 'X';
  out.push_back(refused("bad_magic", bytes));
  bytes = seed;
  bytes[4] = 2;
  out.push_back(refused("other_format_version", bytes));
  bytes = seed;
  bytes[20] ^= 0x01;  // inside the manifest
  out.push_back(refused("manifest_checksum", bytes));
  bytes = seed;
  bytes.back() ^= 0x01;  // inside the last member
  out.push_back(refused("member_checksum", bytes));
  bytes = seed;
  bytes.push_back(0);
  out.push_back(refused("stray_bytes", bytes));
  out.push_back(refused("empty", {}));
  out.push_back(refused("too_large", std::vector<std::uint8_t>(model::kMaxPackageBytes + 1, 0)));

  AvatarPackage other_face = photo;
  other_face.generic_face_version = model::kGenericFaceVersion - 1;
  out.push_back(refused("other_generic_face", model::serialize_avatar_package(other_face)));
  AvatarPackage no_mouth = photo;
  no_mouth.mouth = {};  // serialised as an empty member of no type
  out.push_back(refused("bad_member_type", model::serialize_avatar_package(no_mouth)));
  AvatarPackage folded = photo;
  // Two vertices of the face exchanged: their triangles flip over.
  std::swap(folded.fitted_vertices[30], folded.fitted_vertices[8]);
  out.push_back(refused("folded_fit", model::serialize_avatar_package(folded)));
  return out;
}

}  // namespace fw::test
