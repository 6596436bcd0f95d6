#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "avatar_package_layout.hpp"
#include "package_checksum.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"

namespace fw::model {
namespace {

using nlohmann::json;

struct PackageError : std::runtime_error {
  explicit PackageError(const std::string& what, PackageRefusal kind = PackageRefusal::damaged)
      : std::runtime_error(what), refusal(kind) {}
  PackageRefusal refusal;
};

std::uint32_t get_u32(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
         static_cast<std::uint32_t>(b[at + 2]) << 16 | static_cast<std::uint32_t>(b[at + 3]) << 24;
}

float get_coordinate(std::span<const std::uint8_t> b, std::size_t at) {
  const auto u = static_cast<std::uint16_t>(b[at] | b[at + 1] << 8);
  return static_cast<float>(static_cast<std::int16_t>(u)) / package_layout::kCoordinateScale;
}

std::array<std::uint8_t, 3> read_rgb(const json& manifest, const char* key) {
  const json& v = manifest.at(key);
  if (!v.is_array() || v.size() != 3) throw PackageError(std::string("manifest.") + key + " must be three numbers 0-255");
  std::array<std::uint8_t, 3> rgb{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_number_unsigned() || v[i].get<unsigned>() > 255)
      throw PackageError(std::string("manifest.") + key + " must be three numbers 0-255");
    rgb[i] = static_cast<std::uint8_t>(v[i].get<unsigned>());
  }
  return rgb;
}

void read_mesh(std::span<const std::uint8_t> b, AvatarPackage& package) {
  if (b.size() < 2) throw PackageError("the fit member is truncated");
  const std::size_t count = static_cast<std::size_t>(b[0] | b[1] << 8);
  const std::size_t expected_count = generic_face().skin.positions.size();
  if (count != expected_count)
    throw PackageError("the fit has " + std::to_string(count) + " vertices but this build's generic face has " +
                       std::to_string(expected_count) + "; prepare the avatar again with this version",
                       PackageRefusal::other_generic_face);
  if (b.size() != 2 + 4 * (count + kLandmarkCount)) throw PackageError("the fit member has the wrong size");
  std::size_t at = 2;
  package.fitted_vertices.resize(count);
  for (glm::vec2& p : package.fitted_vertices) p = {get_coordinate(b, at), get_coordinate(b, at + 2)}, at += 4;
  for (glm::vec2& p : package.landmarks) p = {get_coordinate(b, at), get_coordinate(b, at + 2)}, at += 4;
}

PackageImage read_image(std::span<const std::uint8_t> b, const std::string& type, const std::string& name) {
  if (type != "image/webp" && type != "image/png")
    throw PackageError("member " + name + " has type " + type + "; expected image/webp or image/png");
  return {type, {b.begin(), b.end()}};
}

AvatarPackage read_package(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxPackageBytes)
    throw PackageError("the package is " + std::to_string(bytes.size()) + " bytes; at most " +
                       std::to_string(kMaxPackageBytes) + " are accepted");
  if (bytes.size() < package_layout::kHeaderBytes ||
      !std::equal(package_layout::kMagic.begin(), package_layout::kMagic.end(), bytes.begin()))
    throw PackageError("this is not a facewire avatar package (.fwa)");
  AvatarPackage package;
  package.version = bytes[4];
  if (package.version != kAvatarPackageVersion)
    throw PackageError("package version " + std::to_string(package.version) + " is not supported (this build reads " +
                       std::to_string(kAvatarPackageVersion) + "); prepare the avatar again",
                       PackageRefusal::other_format_version);
  const std::size_t manifest_size = get_u32(bytes, 8);
  if (manifest_size > kMaxManifestBytes || package_layout::kHeaderBytes + manifest_size > bytes.size())
    throw PackageError("the package is truncated or its manifest length is damaged");
  const auto manifest_bytes = bytes.subspan(package_layout::kHeaderBytes, manifest_size);
  if (crc_of(manifest_bytes) != get_u32(bytes, 12)) throw PackageError("the manifest's checksum does not match");

  const json manifest = json::parse(manifest_bytes.begin(), manifest_bytes.end(), nullptr, false);
  if (manifest.is_discarded() || !manifest.is_object()) throw PackageError("the manifest is not valid JSON");
  if (manifest.value("format", "") != package_layout::kFormatName) throw PackageError("the manifest is not a facewire avatar's");
  package.generic_face_version = manifest.at("generic_face_version").get<int>();
  if (package.generic_face_version != generic_face().version)
    throw PackageError("the avatar was fitted to generic face version " + std::to_string(package.generic_face_version) +
                       ", this build has version " + std::to_string(generic_face().version) + "; prepare it again",
                       PackageRefusal::other_generic_face);
  package.skin_tone = read_rgb(manifest, "skin_tone");
  package.iris_colour = read_rgb(manifest, "iris_colour");
  const json& rect = manifest.at("closed_lid_rect");
  if (!rect.is_array() || rect.size() != 4) throw PackageError("manifest.closed_lid_rect must be four numbers");
  for (int i = 0; i < 4; ++i) {
    const float v = rect[static_cast<std::size_t>(i)].get<float>();
    if (!(v >= 0.0f && v <= 1.0f)) throw PackageError("manifest.closed_lid_rect must lie within [0,1]");
    package.closed_lid_rect[i] = v;
  }

  // Optional: a package without it gets the generic head's outline.
  if (manifest.contains("head_outline")) {
    const json& outline = manifest.at("head_outline");
    if (!outline.is_array() || outline.size() != generic_face().head.outline.size())
      throw PackageError("manifest.head_outline must be " + std::to_string(generic_face().head.outline.size()) +
                         " radii");
    for (const json& r : outline) {
      const float radius = r.get<float>();
      if (!(radius > 0.0f && radius < 8.0f)) throw PackageError("manifest.head_outline radii must lie in (0, 8)");
      package.head_outline.push_back(radius);
    }
  }

  // Optional: a package without it holds a photo's light.
  if (manifest.contains("texture_light")) {
    const json& light = manifest.at("texture_light");
    if (light == "albedo")
      package.texture_light = TextureLight::albedo;
    else if (light != "photo")
      throw PackageError("manifest.texture_light must be \"photo\" or \"albedo\" (what the colour textures hold); "
                         "leave it out for a photo");
  }

  const json& members = manifest.at("members");
  if (!members.is_array() || members.size() > kMaxPackageMembers) throw PackageError("manifest.members is malformed");
  std::size_t at = package_layout::kHeaderBytes + manifest_size;
  std::vector<std::string> seen;
  for (const json& member : members) {
    const std::string name = member.at("name").get<std::string>();
    const std::string type = member.at("type").get<std::string>();
    const std::size_t size = member.at("size").get<std::size_t>();
    if (size > bytes.size() - at) throw PackageError("the package is truncated (member " + name + " is cut off)");
    const auto data = bytes.subspan(at, size);
    at += size;
    if (crc_of(data) != member.at("crc32").get<std::uint32_t>())
      throw PackageError("member " + name + " is damaged (checksum mismatch)");
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) throw PackageError("member " + name + " appears twice");
    seen.push_back(name);
    if (name == "mesh") {
      if (type != package_layout::kMeshType) throw PackageError("member mesh has the wrong type");
      read_mesh(data, package);
    } else if (name == "face_texture") package.face_texture = read_image(data, type, name);
    else if (name == "closed_lid") package.closed_lid = read_image(data, type, name);
    else if (name == "eye") package.eye = read_image(data, type, name);
    else if (name == "mouth") package.mouth = read_image(data, type, name);
    else if (name == "colour_masks_a") package.colour_masks_a = read_image(data, type, name);
    else if (name == "colour_masks_b") package.colour_masks_b = read_image(data, type, name);
    else if (name == "preview") package.preview = read_image(data, type, name);
    // Unknown members are skipped: a later minor revision may add some.
  }
  if (at != bytes.size()) throw PackageError("the package has " + std::to_string(bytes.size() - at) + " stray bytes at its end");
  for (const char* required : {"mesh", "face_texture", "closed_lid", "mouth", "colour_masks_a", "colour_masks_b", "preview"})
    if (std::find(seen.begin(), seen.end(), required) == seen.end())
      throw PackageError(std::string("the package has no ") + required + " member");

  const auto problems = validate_generic_face(fit_generic_face(generic_face(), package.fitted_vertices));
  if (!problems.empty()) throw PackageError("the fitted face is unsound: " + problems.front());
  return package;
}

}  // namespace

bool parse_avatar_package(std::span<const std::uint8_t> bytes, AvatarPackage& package, std::string& error) {
  PackageRefusal ignored = PackageRefusal::damaged;
  return parse_avatar_package(bytes, package, error, ignored);
}

bool parse_avatar_package(std::span<const std::uint8_t> bytes, AvatarPackage& package, std::string& error,
                          PackageRefusal& why) {
  try {
    package = read_package(bytes);
    return true;
  } catch (const PackageError& e) {
    error = std::string("bad avatar package: ") + e.what();
    why = e.refusal;
  } catch (const json::exception& e) {
    error = std::string("bad avatar package: the manifest is malformed (") + e.what() + ")";
    why = PackageRefusal::damaged;
  }
  return false;
}

}  // namespace fw::model
