#pragma once
// The room as the client shows it: every avatar's face rebuilt from its
// FaceParams and drawn in one space (room_layout), offscreen with OSMesa.
// Avatars whose package has not arrived yet are drawn as the generic face.
// Lives on one thread (it owns the GL context).
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/image.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::client {

/// One avatar in one frame.
struct AvatarFace {
  std::uint32_t avatar = 0;  ///< room-frame avatar id
  codec::FaceParams params;
};

class RoomView {
 public:
  /// nullptr and `error` if the renderer cannot start (see FaceRenderer::create).
  static std::unique_ptr<RoomView> create(const render::RendererOptions& options, std::string& error);

  /// Gives an avatar its face (a decoded package); until then it is drawn
  /// as the generic face. Replaces an earlier appearance (the full package
  /// after the preview).
  void set_appearance(std::uint32_t avatar, std::shared_ptr<const render::AvatarAppearance> appearance);

  /// Draws `faces` (seated left to right in the given order) and returns
  /// the image. Avatars the view knew that are not in `faces` are forgotten.
  model::RgbaImage render(const std::vector<AvatarFace>& faces);

  int width() const { return options_.width; }
  int height() const { return options_.height; }

 private:
  explicit RoomView(const render::RendererOptions& options) : options_(options) {}
  struct Shown {
    std::shared_ptr<const render::AvatarAppearance> appearance;
    render::FaceId face = 0;
    bool uploaded = false;
  };
  void upload(Shown& shown);
  void forget(std::uint32_t avatar);
  bool restart_renderer(std::string& error);

  render::RendererOptions options_;
  std::unique_ptr<render::FaceRenderer> renderer_;
  std::shared_ptr<const render::AvatarAppearance> placeholder_;
  std::map<std::uint32_t, Shown> shown_;
  // FaceRenderer never frees a face: after this many replaced or departed
  // faces the renderer is rebuilt, so a long session's GPU memory stays bounded.
  int retired_faces_ = 0;
  static constexpr int kMaxRetiredFaces = 32;
};

}  // namespace fw::client
