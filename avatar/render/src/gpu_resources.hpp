#pragma once
// Uploading the renderer's resources to GL: shader program, meshes, textures.
#include <optional>
#include <string>
#include <string_view>

#include "fw/model/image.hpp"
#include "colour_mipmaps.hpp"
#include "fw/model/mesh.hpp"
#include "gl_objects.hpp"

namespace fw::render {

/// Compiles and links a vertex + fragment shader pair; nullopt and `error`
/// (with the GL info log) on failure.
std::optional<Program> build_program(std::string_view vertex_source, std::string_view fragment_source,
                                     std::string& error);

/// A mesh in GL buffers: attribute 0 position, 1 normal, 2 uv, 3 the normal
/// of the shape it was uploaded with (the rest shape the texture shows).
struct GpuMesh {
  VertexArray vertex_array;
  Buffer positions, normals, uvs, rest_normals, indices;
  GLsizei index_count = 0;
  /// The first indices draw triangles that read only opaque texels
  /// (opaque_texels.hpp): drawn without alpha to coverage.
  GLsizei opaque_index_count = 0;
};
/// `rest_normals` (the shader's, under which a photo texture saw its light):
/// the mesh's own normals when empty.
GpuMesh upload_mesh(const model::Mesh& mesh, const std::vector<glm::vec3>& rest_normals = {});

/// More triangles over `mesh`'s vertex buffers (a vertex array of their own
/// sharing the buffers), so they follow every update_mesh of `mesh`.
GpuMesh share_vertices(const GpuMesh& mesh, const std::vector<glm::uvec3>& triangles);

/// Replaces the mesh's triangles (the same ones, reordered) with
/// `triangles`, whose first `opaque_count` read only opaque texels.
void set_triangle_order(GpuMesh& gpu, const std::vector<glm::uvec3>& triangles, std::size_t opaque_count);

/// New positions and uvs (and so normals) for a mesh of the same topology;
/// the rest normals stay.
void update_mesh(GpuMesh& gpu, const model::Mesh& mesh);

/// What a texture's bytes hold: colours (sRGB-encoded; the texture holds
/// the square root of their linear light, which the shader squares, see
/// colour_mipmaps.hpp) or plain data such as masks.
enum class TexelEncoding { srgb_colour, linear_data };

/// An RGBA8 texture with mipmaps, clamped at the edges. Rows are flipped on
/// upload because images run top-down and texture v runs up.
Texture upload_texture(const model::RgbaImage& image, TexelEncoding encoding);

/// A colour texture from its levels (square_root_light_mipmaps), as
/// upload_texture makes it from an image.
Texture upload_colour_levels(const std::vector<MipLevel>& levels);

}  // namespace fw::render
