#include "fw/model/avatar_package.hpp"

#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "package_checksum.hpp"

namespace fw::model {
namespace {

// A package with an identity fit and stand-in image bytes: the reader checks
// structure and fit; decoding images is the renderer's job.
AvatarPackage sample_package() {
  AvatarPackage p;
  p.generic_face_version = generic_face().version;
  for (const glm::vec3& v : generic_face().skin.positions) p.fitted_vertices.emplace_back(v.x, v.y);
  const auto tmpl = landmark_template();
  std::copy(tmpl.begin(), tmpl.end(), p.landmarks.begin());
  p.skin_tone = {200, 150, 130};
  p.iris_colour = {60, 80, 120};
  p.closed_lid_rect = {0.2f, 0.5f, 0.8f, 0.7f};
  std::uint8_t fill = 1;
  for (PackageImage* image : {&p.face_texture, &p.closed_lid, &p.eye, &p.mouth, &p.colour_masks_a, &p.colour_masks_b, &p.preview}) {
    image->type = "image/webp";
    image->bytes.assign(40 + fill, fill);
    ++fill;
  }
  return p;
}

std::string package_error(const std::vector<std::uint8_t>& bytes) {
  AvatarPackage p;
  std::string error;
  EXPECT_FALSE(parse_avatar_package(bytes, p, error));
  return error;
}

TEST(AvatarPackage, RoundTrips) {
  const AvatarPackage original = sample_package();
  const auto bytes = serialize_avatar_package(original);
  AvatarPackage parsed;
  std::string error;
  ASSERT_TRUE(parse_avatar_package(bytes, parsed, error)) << error;
  ASSERT_EQ(parsed.fitted_vertices.size(), original.fitted_vertices.size());
  for (std::size_t i = 0; i < parsed.fitted_vertices.size(); ++i) {
    EXPECT_NEAR(parsed.fitted_vertices[i].x, original.fitted_vertices[i].x, 1.0f / 4096);
    EXPECT_NEAR(parsed.fitted_vertices[i].y, original.fitted_vertices[i].y, 1.0f / 4096);
  }
  EXPECT_EQ(parsed.skin_tone, original.skin_tone);
  EXPECT_EQ(parsed.iris_colour, original.iris_colour);
  EXPECT_EQ(parsed.closed_lid_rect, original.closed_lid_rect);
  EXPECT_EQ(parsed.eye.bytes, original.eye.bytes);
  EXPECT_EQ(parsed.preview.bytes, original.preview.bytes);
  EXPECT_EQ(serialize_avatar_package(parsed), bytes) << "stable when written again";
}

TEST(AvatarPackage, TheEyeLayerIsOptional) {
  AvatarPackage p = sample_package();
  p.eye.bytes.clear();
  AvatarPackage parsed;
  std::string error;
  ASSERT_TRUE(parse_avatar_package(serialize_avatar_package(p), parsed, error)) << error;
  EXPECT_TRUE(parsed.eye.bytes.empty());
  p.mouth.bytes.clear();
  p.mouth.type.clear();
  EXPECT_FALSE(parse_avatar_package(serialize_avatar_package(p), parsed, error)) << "other layers are not optional";
}

TEST(AvatarPackage, EveryTruncationIsAnError) {
  const auto bytes = serialize_avatar_package(sample_package());
  for (std::size_t cut = 0; cut < bytes.size(); cut += 7) {
    const std::string error = package_error({bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(cut)});
    EXPECT_FALSE(error.empty()) << cut;
  }
}

TEST(AvatarPackage, EveryFlippedByteIsCaught) {
  const auto bytes = serialize_avatar_package(sample_package());
  // Every byte is covered by the magic, a length, a checksum or the data it
  // guards; flags and reserved bytes (5..7) are not meaningful yet.
  for (std::size_t at = 0; at < bytes.size(); at += 3) {
    if (at >= 5 && at < 8) continue;
    auto damaged = bytes;
    damaged[at] ^= 0x40;
    EXPECT_FALSE(package_error(damaged).empty()) << "byte " << at;
  }
}

TEST(AvatarPackage, SaysWhatIsWrong) {
  const auto bytes = serialize_avatar_package(sample_package());
  auto other = bytes;
  other[0] = 'X';
  EXPECT_NE(package_error(other).find("not a facewire avatar package"), std::string::npos);
  auto version = bytes;
  version[4] = 9;
  EXPECT_NE(package_error(version).find("version 9 is not supported"), std::string::npos);
  auto stray = bytes;
  stray.push_back(0);
  EXPECT_NE(package_error(stray).find("stray bytes"), std::string::npos);
  auto member = bytes;
  member[member.size() - 5] ^= 1;  // inside the last member (preview)
  EXPECT_NE(package_error(member).find("preview is damaged"), std::string::npos);
  std::vector<std::uint8_t> huge(kMaxPackageBytes + 1, 0);
  EXPECT_NE(package_error(huge).find("at most"), std::string::npos);
}

TEST(AvatarPackage, RefusesAFoldedFit) {
  AvatarPackage p = sample_package();
  std::swap(p.fitted_vertices[100], p.fitted_vertices[150]);
  EXPECT_NE(package_error(serialize_avatar_package(p)).find("fitted face is unsound"), std::string::npos);
}

TEST(AvatarPackage, RefusesAFitForAnotherGenericFace) {
  AvatarPackage p = sample_package();
  p.fitted_vertices.pop_back();
  EXPECT_NE(package_error(serialize_avatar_package(p)).find("prepare the avatar again"), std::string::npos);
}

// A server keeps packages and prepares again, from the photo, those of
// another format or generic face; damage it refuses. The reader says which.
PackageRefusal refusal_of(const std::vector<std::uint8_t>& bytes) {
  AvatarPackage p;
  std::string error;
  PackageRefusal why = PackageRefusal::damaged;
  EXPECT_FALSE(parse_avatar_package(bytes, p, error, why));
  return why;
}

TEST(AvatarPackage, SaysWhetherItIsOutOfDateOrDamaged) {
  AvatarPackage older_face = sample_package();
  older_face.generic_face_version -= 1;
  EXPECT_EQ(refusal_of(serialize_avatar_package(older_face)), PackageRefusal::other_generic_face);
  AvatarPackage other_mesh = sample_package();
  other_mesh.fitted_vertices.pop_back();
  EXPECT_EQ(refusal_of(serialize_avatar_package(other_mesh)), PackageRefusal::other_generic_face);
  AvatarPackage newer_format = sample_package();
  newer_format.version = kAvatarPackageVersion + 1;
  EXPECT_EQ(refusal_of(serialize_avatar_package(newer_format)), PackageRefusal::other_format_version);

  auto damaged = serialize_avatar_package(sample_package());
  damaged[damaged.size() - 5] ^= 1;
  EXPECT_EQ(refusal_of(damaged), PackageRefusal::damaged);
  auto bad_manifest = serialize_avatar_package(sample_package());
  bad_manifest[20] ^= 0x40;
  EXPECT_EQ(refusal_of(bad_manifest), PackageRefusal::damaged);
  EXPECT_EQ(refusal_of({'F', 'W'}), PackageRefusal::damaged);
}

TEST(AvatarPackage, RefusesAnUnknownImageType) {
  AvatarPackage p = sample_package();
  p.eye.type = "image/gif";
  EXPECT_NE(package_error(serialize_avatar_package(p)).find("expected image/webp or image/png"), std::string::npos);
}

TEST(AvatarPackage, SaysWhatItsTexturesHoldAPhotosLightByDefault) {
  AvatarPackage parsed;
  std::string error;
  const auto photo = serialize_avatar_package(sample_package());
  ASSERT_TRUE(parse_avatar_package(photo, parsed, error)) << error;
  EXPECT_EQ(parsed.texture_light, TextureLight::photo);
  const std::string text(photo.begin(), photo.end());
  EXPECT_EQ(text.find("texture_light"), std::string::npos) << "a photo's package is written as before";

  AvatarPackage procedural = sample_package();
  procedural.texture_light = TextureLight::albedo;
  ASSERT_TRUE(parse_avatar_package(serialize_avatar_package(procedural), parsed, error)) << error;
  EXPECT_EQ(parsed.texture_light, TextureLight::albedo);
}

TEST(AvatarPackage, RefusesATextureLightItDoesNotKnow) {
  AvatarPackage procedural = sample_package();
  procedural.texture_light = TextureLight::albedo;
  auto bytes = serialize_avatar_package(procedural);
  // The manifest (at 16, its length at 8) with another value, its checksum
  // (at 12) made right again: only the value is wrong.
  const std::size_t length = bytes[8] | bytes[9] << 8 | bytes[10] << 16 | static_cast<std::size_t>(bytes[11]) << 24;
  std::string manifest(bytes.begin() + 16, bytes.begin() + 16 + static_cast<std::ptrdiff_t>(length));
  const std::size_t at = manifest.find("\"albedo\"");
  ASSERT_NE(at, std::string::npos);
  manifest.replace(at, 8, "\"albedx\"");
  std::copy(manifest.begin(), manifest.end(), bytes.begin() + 16);
  const std::uint32_t crc = crc_of({reinterpret_cast<const std::uint8_t*>(manifest.data()), manifest.size()});
  for (int i = 0; i < 4; ++i) bytes[12 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  const std::string error = package_error(bytes);
  EXPECT_NE(error.find("manifest.texture_light must be \"photo\" or \"albedo\""), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::model
