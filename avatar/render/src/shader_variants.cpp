#include "shader_variants.hpp"

#include <vector>

#include "gpu_resources.hpp"

namespace fw::render {

std::string with_defines(std::string_view source, std::span<const std::string_view> defines) {
  const std::size_t line_end = source.find('\n');
  const std::size_t split = line_end == std::string_view::npos ? source.size() : line_end + 1;
  std::string out(source.substr(0, split));
  if (line_end == std::string_view::npos) out += '\n';
  for (std::string_view name : defines) {
    out += "#define ";
    out += name;
    out += '\n';
  }
  out += source.substr(split);
  return out;
}

PartShader skin_shader(bool lids_closing, bool blood) {
  if (lids_closing) return blood ? PartShader::skin_closing_lids_with_blood : PartShader::skin_closing_lids;
  return blood ? PartShader::skin_with_blood : PartShader::plain;
}

std::size_t shader_index(PartShader part, model::TextureLight light) {
  return static_cast<std::size_t>(part) + (light == model::TextureLight::albedo ? kPartShaderCount : 0);
}

std::string shader_name(std::size_t index) {
  static constexpr std::array<std::string_view, kPartShaderCount> kParts{
      "plain", "skin_closing_lids", "skin_closing_lids_with_blood", "skin_with_blood", "eye", "matte"};
  std::string name(kParts[index % kPartShaderCount]);
  if (index >= kPartShaderCount) name += "+albedo";
  return name;
}

std::optional<std::array<ShaderVariant, kShaderCount>> build_part_shaders(std::string_view vertex_source,
                                                                          std::string_view fragment_source,
                                                                          bool alpha_test, std::string& error) {
  std::array<ShaderVariant, kShaderCount> variants;
  for (std::size_t i = 0; i < kShaderCount; ++i) {
    // Colour textures come from upload_texture (colour_mipmaps.hpp).
    std::vector<std::string_view> defines{"FW_SQUARE_ROOT_COLOUR"};
    if (alpha_test) defines.push_back("FW_ALPHA_TEST");
    if (i >= kPartShaderCount) defines.push_back("FW_ALBEDO");
    switch (static_cast<PartShader>(i % kPartShaderCount)) {
      case PartShader::plain: break;
      case PartShader::skin_closing_lids: defines.push_back("FW_CLOSED_LID"); break;
      case PartShader::skin_closing_lids_with_blood: defines.insert(defines.end(), {"FW_CLOSED_LID", "FW_BLOOD"}); break;
      case PartShader::skin_with_blood: defines.push_back("FW_BLOOD"); break;
      case PartShader::eye: defines.push_back("FW_SPECULAR"); break;
      case PartShader::matte: defines.push_back("FW_MATTE"); break;
    }
    auto program = build_program(with_defines(vertex_source, defines), with_defines(fragment_source, defines), error);
    if (!program) return std::nullopt;
    const GLuint p = program->get();
    const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    variants[i].uniforms = {at("u_model"),      at("u_view_projection"), at("u_camera_position"),
                            at("u_light_direction"), at("u_specular"), at("u_texture"),
                            at("u_closed_lid"), at("u_closed_lid_rect"), at("u_lid_closure"),
                            at("u_masks_a"),    at("u_masks_b"),         at("u_blush_a"),
                            at("u_blush_sides"), at("u_pallor"), at("u_skin_specular")};
    variants[i].program = std::move(*program);
  }
  return variants;
}

}  // namespace fw::render
