#pragma once
// The shaders' variants (see the head of shaders/face.frag): one program per
// kind of part and per kind of texture light, and where each one's uniforms
// live.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "fw/model/avatar_package.hpp"
#include "gl_objects.hpp"

namespace fw::render {

// The skin uses plain when its lids are open and it has no blood colour:
// those lookups would change nothing, and llvmpipe pays for every one.
// The mouth cavity and the head shell use matte: plain without the skin's
// specular (FW_MATTE), whose maths and two varyings they would pay for with
// a zero scale.
enum class PartShader { plain, skin_closing_lids, skin_closing_lids_with_blood, skin_with_blood, eye, matte };
inline constexpr std::size_t kPartShaderCount = 6;
/// Every part's variant once for photo textures and once for albedo (FW_ALBEDO).
inline constexpr std::size_t kShaderCount = 2 * kPartShaderCount;

/// Where the variant of `part` for textures holding `light` is among the built ones.
std::size_t shader_index(PartShader part, model::TextureLight light);

/// The variant's name, for profiles: the part's ("plain", "skin_closing_lids",
/// "skin_closing_lids_with_blood", "skin_with_blood", "eye", "matte"), "+albedo" for FW_ALBEDO.
std::string shader_name(std::size_t index);

/// The skin's variant for a frame: `lids_closing` if either lid closes at
/// all, `blood` if any blush or pallor shows.
PartShader skin_shader(bool lids_closing, bool blood);

/// `source` with a `#define NAME` line for each of `defines` after its first
/// line (the #version line, which must stay first).
std::string with_defines(std::string_view source, std::span<const std::string_view> defines);

/// Where a program's uniforms are; -1 for those its variant does not have.
struct ShaderUniforms {
  GLint model = -1, view_projection = -1, camera_position = -1, light_direction = -1, specular = -1, texture = -1;
  GLint closed_lid = -1, closed_lid_rect = -1, lid_closure = -1, masks_a = -1, masks_b = -1, blush_a = -1,
        blush_sides = -1, pallor = -1, skin_specular = -1;
};

struct ShaderVariant {
  Program program;
  ShaderUniforms uniforms;
};

/// Builds every variant (both stages get its defines); `alpha_test` (no
/// multisampling) makes alpha under 0.5 a hole instead of partial coverage.
/// nullopt and `error` on failure.
std::optional<std::array<ShaderVariant, kShaderCount>> build_part_shaders(std::string_view vertex_source,
                                                                               std::string_view fragment_source,
                                                                               bool alpha_test, std::string& error);

}  // namespace fw::render
