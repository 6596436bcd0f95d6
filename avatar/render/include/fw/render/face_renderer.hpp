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

#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/model/image.hpp"
#include "fw/render/camera.hpp"
#include "fw/render/frame_profile.hpp"

namespace fw::render {

struct RendererOptions {
  int width = 512;   ///< pixels, 16..4096
  int height = 512;  ///< pixels, 16..4096
  int samples = 4;   ///< multisample anti-aliasing; 0 turns it off
  glm::vec3 background{0.13f, 0.14f, 0.17f};
};

/// The textures of one face: skin (with alpha holes at the eyes), eyeball and
/// mouth interior (see model/procedural_texture.hpp for how they map), the
/// closed-lid skin and the vascular masks (model/vascular_masks.hpp). An
/// empty closed-lid or mask image turns that effect off; an empty eye image
/// is the non-masking mode: the eye holes are filled with the skin texture
/// (the photo's own eyes) and no eyeball is drawn. `light` says whether the
/// colour textures hold a photo's light (relit only where the face turns)
/// or albedo (lit by the renderer's sky, ground and key light).
struct FaceTextures {
  model::TextureLight light = model::TextureLight::photo;
  model::RgbaImage skin;
  model::RgbaImage eye;
  model::RgbaImage mouth;
  model::RgbaImage closed_lid;
  glm::vec4 closed_lid_rect{0.0f};  ///< (u0, v0, u1, v1) in the texture frame
  model::RgbaImage masks_a;         ///< forehead, left cheek, right cheek
  model::RgbaImage masks_b;         ///< nose, sides, whole face
};

using FaceId = std::uint32_t;

/// One face in one frame.
struct FaceDraw {
  FaceId face = 0;
  glm::mat4 model{1.0f};  ///< head_transform(...) of this face
  /// Each eye's (yaw, pitch) in radians, indexed by model::Side.
  std::array<glm::vec2, 2> eye_yaw_pitch_rad{};
  glm::vec2 lid_closure{0.0f};   ///< person's right, left, 0..1 (the closed-lid skin)
  std::array<float, 5> blush{};  ///< codec::ColourRegion order, 0..1
  float pallor = 0;              ///< 0..1
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

  /// Replaces a face's skin shape (positions and texture coordinates, #V of
  /// the face it was added with), e.g. model::reconstruct_face's result.
  void set_face_shape(FaceId face, std::span<const glm::vec3> positions, std::span<const glm::vec2> uvs);

  /// Draws `draws` as seen by `camera` and reads the image back.
  model::RgbaImage render(std::span<const FaceDraw> draws, const Camera& camera);

  /// While `profile` is set (not null), render() waits for each part of a
  /// frame to finish and adds its time to `profile`, which must outlive
  /// the setting; nullptr stops it. For measuring only: it slows frames.
  void set_profile(FrameProfile* profile);

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
