#include "gpu_resources.hpp"

#include <algorithm>
#include <vector>

#include "colour_mipmaps.hpp"
#include "fw/model/mesh.hpp"

namespace fw::render {
namespace {

std::optional<Shader> compile(GLenum type, std::string_view source, std::string& error) {
  Shader shader(glCreateShader(type));
  const GLchar* text = source.data();
  const auto length = static_cast<GLint>(source.size());
  glShaderSource(shader.get(), 1, &text, &length);
  glCompileShader(shader.get());
  GLint ok = 0;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  char log[2048] = {};
  glGetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
  error = std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader does not compile: " + log;
  return std::nullopt;
}

template <typename T>
Buffer array_buffer(GLuint attribute, const std::vector<T>& data, GLint components) {
  auto buffer = generate<Buffer, glGenBuffers>();
  glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(attribute);
  glVertexAttribPointer(attribute, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  return buffer;
}

}  // namespace

std::optional<Program> build_program(std::string_view vertex_source, std::string_view fragment_source,
                                     std::string& error) {
  auto vertex = compile(GL_VERTEX_SHADER, vertex_source, error);
  if (!vertex) return std::nullopt;
  auto fragment = compile(GL_FRAGMENT_SHADER, fragment_source, error);
  if (!fragment) return std::nullopt;
  Program program(glCreateProgram());
  glAttachShader(program.get(), vertex->get());
  glAttachShader(program.get(), fragment->get());
  glLinkProgram(program.get());
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (ok) return program;
  char log[2048] = {};
  glGetProgramInfoLog(program.get(), sizeof log, nullptr, log);
  error = std::string("shader program does not link: ") + log;
  return std::nullopt;
}

GpuMesh upload_mesh(const model::Mesh& mesh, const std::vector<glm::vec3>& rest_normals) {
  GpuMesh gpu;
  gpu.vertex_array = generate<VertexArray, glGenVertexArrays>();
  glBindVertexArray(gpu.vertex_array.get());
  gpu.positions = array_buffer(0, mesh.positions, 3);
  // Welded: the head shell's seams must not crease its shading. A mesh
  // updated every frame (update_mesh, the skin) has no coincident vertices.
  const std::vector<glm::vec3> normals = model::welded_vertex_normals(mesh);
  gpu.normals = array_buffer(1, normals, 3);
  gpu.uvs = array_buffer(2, mesh.uvs, 2);
  gpu.rest_normals = array_buffer(3, rest_normals.empty() ? normals : rest_normals, 3);
  gpu.indices = generate<Buffer, glGenBuffers>();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.triangles.size() * sizeof(glm::uvec3)),
               mesh.triangles.data(), GL_STATIC_DRAW);
  gpu.index_count = static_cast<GLsizei>(mesh.triangles.size() * 3);
  glBindVertexArray(0);
  return gpu;
}

GpuMesh share_vertices(const GpuMesh& mesh, const std::vector<glm::uvec3>& triangles) {
  GpuMesh shared;
  shared.vertex_array = generate<VertexArray, glGenVertexArrays>();
  glBindVertexArray(shared.vertex_array.get());
  const GLuint buffers[4] = {mesh.positions.get(), mesh.normals.get(), mesh.uvs.get(), mesh.rest_normals.get()};
  const GLint sizes[4] = {3, 3, 2, 3};
  for (GLuint attribute = 0; attribute < 4; ++attribute) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers[attribute]);
    glEnableVertexAttribArray(attribute);
    glVertexAttribPointer(attribute, sizes[attribute], GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  shared.indices = generate<Buffer, glGenBuffers>();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, shared.indices.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(glm::uvec3)),
               triangles.data(), GL_STATIC_DRAW);
  shared.index_count = static_cast<GLsizei>(triangles.size() * 3);
  glBindVertexArray(0);
  return shared;
}

void set_triangle_order(GpuMesh& gpu, const std::vector<glm::uvec3>& triangles, std::size_t opaque_count) {
  glBindVertexArray(gpu.vertex_array.get());  // the element buffer binding is the vertex array's
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(glm::uvec3)),
               triangles.data(), GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
  gpu.index_count = static_cast<GLsizei>(triangles.size() * 3);
  gpu.opaque_index_count = static_cast<GLsizei>(std::min(opaque_count, triangles.size()) * 3);
}

void update_mesh(GpuMesh& gpu, const model::Mesh& mesh) {
  const auto replace = [](const Buffer& buffer, const auto& data) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(data.size() * sizeof(data[0])), data.data());
  };
  replace(gpu.positions, mesh.positions);
  replace(gpu.normals, model::vertex_normals(mesh));
  replace(gpu.uvs, mesh.uvs);
}

namespace {

void set_sampling() {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

Texture upload_colour_levels(const std::vector<MipLevel>& levels) {
  auto texture = generate<Texture, glGenTextures>();
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t i = 0; i < levels.size(); ++i)
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(i), GL_RGBA8, levels[i].width, levels[i].height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, levels[i].texels.data());
  set_sampling();
  return texture;
}

Texture upload_texture(const model::RgbaImage& image, TexelEncoding encoding) {
  // Made here, once, rather than decoded on every lookup (colour_mipmaps.hpp).
  if (encoding == TexelEncoding::srgb_colour) return upload_colour_levels(square_root_light_mipmaps(image));
  auto texture = generate<Texture, glGenTextures>();
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> flipped(image.pixels.size());
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.at(0, y), row, flipped.data() + static_cast<std::size_t>(image.height - 1 - y) * row);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  set_sampling();
  return texture;
}

}  // namespace fw::render
