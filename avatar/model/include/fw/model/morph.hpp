#pragma once
// A morph: how far each skin vertex moves, and how far its texture
// coordinate slides, at full intensity. Expressive textures: the apparent
// motion of the skin's picture is vertex_delta - uv_delta * texture size,
// so a brow can rise by moving the mesh, by sliding the texture over it, or
// by both.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fw::model {

struct Morph {
  std::vector<glm::vec3> vertex_delta;  ///< #V, model units
  std::vector<glm::vec2> uv_delta;      ///< #V, texture uv units
};

}  // namespace fw::model
