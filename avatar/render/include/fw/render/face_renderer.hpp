#pragma once
// The renderer: draws one or several faces (skin with eye holes, eyeballs
// behind them, mouth cavity behind the lips) with simple lighting into an
// offscreen image. One renderer per thread; it owns its GL context.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/image.hpp"
#include "fw/render/camera.hpp"

namespace fw::render {

struct RendererOptions {
  int width = 512;   ///< pixels, 16..4096
  int height = 512;  ///< pixels, 16..4096
  int samples = 4;   ///< multisample anti-aliasing; 0 turns it off
  glm::vec3 background{0.13f, 0.14f, 0.17f};
};

/// The textures of one face: skin (with alpha holes at the eyes), eyeball and
/// mouth interior. See model/procedural_texture.hpp for how they map.
struct FaceTextures {
  model::RgbaImage skin;
  model::RgbaImage eye;
  model::RgbaImage mouth;
};

using FaceId = std::uint32_t;

/// One face in one frame.
struct FaceDraw {
  FaceId face = 0;
  glm::mat4 model{1.0f};  ///< head_transform(...) of this face
  /// Each eye's (yaw, pitch) in radians, indexed by model::Side.
  std::array<glm::vec2, 2> eye_yaw_pitch_rad{};
};

class FaceRenderer {
 public:
  /// nullptr and `error` if the GL context, the shaders or the framebuffers
  /// cannot be set up, or the options are out of range.
  static std::unique_ptr<FaceRenderer> create(const RendererOptions& options, std::string& error);
  ~FaceRenderer();
  FaceRenderer(const FaceRenderer&) = delete;
  FaceRenderer& operator=(const FaceRenderer&) = delete;

  /// Uploads a face's meshes and textures; the id stays valid for the
  /// renderer's life.
  FaceId add_face(const model::GenericFace& face, const FaceTextures& textures);

  /// Draws `draws` as seen by `camera` and reads the image back.
  model::RgbaImage render(std::span<const FaceDraw> draws, const Camera& camera);

  /// GL_RENDERER of the context (llvmpipe on machines without a GPU).
  std::string renderer_name();
  int width() const;
  int height() const;

 private:
  FaceRenderer();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::render
