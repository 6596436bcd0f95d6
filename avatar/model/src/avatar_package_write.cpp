#include <cmath>

#include <nlohmann/json.hpp>

#include "avatar_package_layout.hpp"
#include "package_checksum.hpp"
#include "fw/model/avatar_package.hpp"

namespace fw::model {
namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void put_coordinate(std::vector<std::uint8_t>& out, float v) {
  const auto q = static_cast<std::int16_t>(std::lround(std::clamp(v * package_layout::kCoordinateScale, -32767.0f, 32767.0f)));
  const auto u = static_cast<std::uint16_t>(q);
  out.push_back(static_cast<std::uint8_t>(u & 0xff));
  out.push_back(static_cast<std::uint8_t>(u >> 8));
}

std::vector<std::uint8_t> encode_mesh(const AvatarPackage& package) {
  std::vector<std::uint8_t> out;
  const auto count = static_cast<std::uint16_t>(package.fitted_vertices.size());
  out.push_back(static_cast<std::uint8_t>(count & 0xff));
  out.push_back(static_cast<std::uint8_t>(count >> 8));
  for (const glm::vec2& p : package.fitted_vertices) put_coordinate(out, p.x), put_coordinate(out, p.y);
  for (const glm::vec2& p : package.landmarks) put_coordinate(out, p.x), put_coordinate(out, p.y);
  return out;
}

}  // namespace

std::vector<std::uint8_t> serialize_avatar_package(const AvatarPackage& package) {
  const std::vector<std::uint8_t> mesh = encode_mesh(package);
  struct Member {
    std::string_view name;
    std::string_view type;
    std::span<const std::uint8_t> bytes;
  };
  const Member members[] = {
      {"mesh", package_layout::kMeshType, mesh},
      {"face_texture", package.face_texture.type, package.face_texture.bytes},
      {"closed_lid", package.closed_lid.type, package.closed_lid.bytes},
      {"eye", package.eye.type, package.eye.bytes},
      {"mouth", package.mouth.type, package.mouth.bytes},
      {"colour_masks_a", package.colour_masks_a.type, package.colour_masks_a.bytes},
      {"colour_masks_b", package.colour_masks_b.type, package.colour_masks_b.bytes},
      {"preview", package.preview.type, package.preview.bytes},
  };
  nlohmann::json manifest = {
      {"format", package_layout::kFormatName},
      {"generic_face_version", package.generic_face_version},
      {"skin_tone", package.skin_tone},
      {"iris_colour", package.iris_colour},
      {"closed_lid_rect", {package.closed_lid_rect.x, package.closed_lid_rect.y, package.closed_lid_rect.z,
                           package.closed_lid_rect.w}},
      {"members", nlohmann::json::array()},
  };
  // Millimetre-fine radii keep the manifest short (about 200 bytes for 32).
  if (!package.head_outline.empty()) {
    nlohmann::json outline = nlohmann::json::array();
    for (const float r : package.head_outline) outline.push_back(std::round(r * 1000.0f) / 1000.0f);
    manifest["head_outline"] = outline;
  }
  // Written only for albedo, so that a photo's package stays as it was.
  if (package.texture_light == TextureLight::albedo) manifest["texture_light"] = "albedo";
  // The eye layer is optional (a package without it is shown in non-masking mode).
  const auto present = [](const Member& m) { return m.name != "eye" || !m.bytes.empty(); };
  for (const Member& m : members)
    if (present(m)) manifest["members"].push_back({{"name", m.name}, {"type", m.type}, {"size", m.bytes.size()}, {"crc32", crc_of(m.bytes)}});
  const std::string text = manifest.dump();

  std::vector<std::uint8_t> out(package_layout::kMagic.begin(), package_layout::kMagic.end());
  out.push_back(package.version);
  out.push_back(0);  // flags, none defined
  out.push_back(0);
  out.push_back(0);  // reserved
  put_u32(out, static_cast<std::uint32_t>(text.size()));
  put_u32(out, crc_of({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}));
  out.insert(out.end(), text.begin(), text.end());
  for (const Member& m : members)
    if (present(m)) out.insert(out.end(), m.bytes.begin(), m.bytes.end());
  return out;
}

}  // namespace fw::model
