#pragma once
// The avatar package (.fwa): one file that carries everything a client needs
// to show one person's face: the aligned face texture, eye and closed-lid
// layers, vascular colour masks, a tiny preview and the fit of the generic
// face. Written by avatar/photo, read by every client. The byte layout is
// documented in avatar/photo/FORMAT.md.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "fw/model/landmark_template.hpp"

namespace fw::model {

inline constexpr std::uint8_t kAvatarPackageVersion = 1;
/// Bounds on what a reader accepts: a package is small by design (about
/// 20 KB), so anything near these is damage or abuse, not a photo.
inline constexpr std::size_t kMaxPackageBytes = 512 * 1024;
inline constexpr std::size_t kMaxManifestBytes = 16 * 1024;
inline constexpr std::size_t kMaxPackageMembers = 16;

/// What a package's colour textures hold. A photo's hold the light it was
/// taken in, so a renderer only relights where the face turns from it; a
/// procedural face's are albedo (the surface's own colour), which a
/// renderer lights in full.
enum class TextureLight : std::uint8_t { photo, albedo };

/// One image member: encoded bytes (WebP or PNG) and the media type.
struct PackageImage {
  std::string type;                ///< "image/webp" or "image/png"
  std::vector<std::uint8_t> bytes; ///< the encoded image
};

struct AvatarPackage {
  std::uint8_t version = kAvatarPackageVersion;
  int generic_face_version = 0;  ///< the generic face the fit was made for
  /// Where each generic skin vertex lies on this face, model units (x, y);
  /// depth stays the generic face's. #V of the generic face's skin.
  std::vector<glm::vec2> fitted_vertices;
  /// The person's 68 landmarks in the model frame (eye centres at (+-0.5, 0)).
  std::array<glm::vec2, kLandmarkCount> landmarks{};
  /// The person's silhouette seen from the front, as the radius on each ray
  /// of the generic head's outline (model units from its centre); empty for
  /// the generic head's. See fw/model/head_shell.hpp.
  std::vector<float> head_outline;
  std::array<std::uint8_t, 3> skin_tone{};   ///< sRGB, median of forehead and cheeks
  std::array<std::uint8_t, 3> iris_colour{}; ///< sRGB, sampled from the photo
  TextureLight texture_light = TextureLight::photo;  ///< the manifest's optional "texture_light"
  /// Face texture over the generic face's texture frame: alpha 0 inside the
  /// eyes and outside the person's matte (the background), soft at its edge.
  PackageImage face_texture;
  /// Skin over the eyes for blinks: a crop of the face texture with the eye
  /// holes filled from the surrounding lids, placed at `closed_lid_rect`.
  PackageImage closed_lid;
  glm::vec4 closed_lid_rect{0.0f};  ///< (u0, v0, u1, v1) in face-texture uv, v up
  /// Eyeball texture in the EyeLayer mapping (see generic_face.hpp). Empty
  /// (and the member absent) for a package without an eye layer: its face
  /// texture keeps the photo's eyes (non-masking mode).
  PackageImage eye;
  /// Mouth interior over the fitted mouth cavity's uv: what the photo shows
  /// between the lips (teeth, if the person smiles with them), darkness beyond.
  PackageImage mouth;
  /// Vascular region masks over the texture frame, one channel per region:
  /// colour_masks_a = (forehead, cheek_left, cheek_right), colour_masks_b =
  /// (nose, sides, whole face), in codec::ColourRegion order plus the face.
  PackageImage colour_masks_a;
  PackageImage colour_masks_b;
  /// A thumbnail of the face for lists and placeholders.
  PackageImage preview;
};

/// Serialises a package (the inverse of parse_avatar_package).
std::vector<std::uint8_t> serialize_avatar_package(const AvatarPackage& package);

/// Why a package was refused. A package made for another package format or
/// another generic face is sound, only out of date: whoever holds the photo
/// it was made from can prepare it again. Anything else is damage.
enum class PackageRefusal {
  damaged,                ///< not a package, cut off, a checksum mismatch, malformed, unsound
  other_format_version,   ///< the header's format version is not kAvatarPackageVersion
  other_generic_face,     ///< the fit was made for another generic face than this build's
};

/// Parses and validates a package: header, sizes, checksums, manifest,
/// every member present and of an allowed type, the fit matching the
/// generic face this build carries and producing a sound mesh.
/// @param[in]  bytes    the file's contents
/// @param[out] package  the package, untouched on failure
/// @param[out] error    what is wrong and what to do, on failure
/// @return true on success
bool parse_avatar_package(std::span<const std::uint8_t> bytes, AvatarPackage& package, std::string& error);
/// The same, and on failure also `why` the package was refused.
bool parse_avatar_package(std::span<const std::uint8_t> bytes, AvatarPackage& package, std::string& error,
                          PackageRefusal& why);

}  // namespace fw::model
