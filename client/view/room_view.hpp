#pragma once
// The room as the client shows it, from the viewer's own place at the
// table (first_person_layout): the others' faces rebuilt from their
// FaceParams, each re-aimed at where its attention target sits in this view
// (gaze_reaim), with their names under them, the last chat line as a caption
// and the viewer's own face in a self-view tile; rendered offscreen with
// OSMesa. Avatars whose package has not arrived yet are drawn as the generic
// face; the self view shows the viewer's own package or photo from the first
// frame. Lives on one thread (it owns the GL context).
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/image.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"
#include "gaze_reaim.hpp"
#include "room_scene.hpp"

namespace fw::client {

class RoomView {
 public:
  /// nullptr and `error` if the renderer cannot start (see FaceRenderer::create).
  static std::unique_ptr<RoomView> create(const render::RendererOptions& options, std::string& error);

  /// Gives an avatar its face (a decoded package); until then it is drawn
  /// as the generic face. Replaces an earlier appearance (the full package
  /// after the preview).
  void set_appearance(std::uint32_t avatar, std::shared_ptr<const render::AvatarAppearance> appearance);

  /// The viewer's own face before the server has sent anything: the package
  /// it uploaded, or else the photo it uploaded (shown flat in the tile until
  /// its avatar's package arrives). Either may be null / empty.
  void set_self_look(std::shared_ptr<const render::AvatarAppearance> appearance, model::RgbaImage photo);

  /// Draws `scene` and returns the image. Avatars the view knew that are not
  /// in the scene are forgotten.
  model::RgbaImage render(const RoomScene& scene);

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
  void forget_absent(const RoomScene& scene);
  render::FaceDraw draw_of(Shown& shown, const codec::FaceParams& params, const glm::mat4& place);
  const render::AvatarAppearance& appearance_of(const Shown& shown) const;
  /// The self view's face, or null when the tile shows the photo instead.
  Shown* self_face(const RoomScene& scene);

  render::RendererOptions options_;
  std::unique_ptr<render::FaceRenderer> renderer_;
  std::shared_ptr<const render::AvatarAppearance> placeholder_;
  std::map<std::uint32_t, Shown> shown_;
  std::map<std::uint32_t, GazeBlend> blends_;  ///< by avatar: its correction while its target changes
  Shown self_;                                 ///< the self view's face (its own GL face)
  std::shared_ptr<const render::AvatarAppearance> self_appearance_;
  model::RgbaImage self_photo_;
  // FaceRenderer never frees a face: after this many replaced or departed
  // faces the renderer is rebuilt, so a long session's GPU memory stays bounded.
  int retired_faces_ = 0;
  static constexpr int kMaxRetiredFaces = 32;
};

}  // namespace fw::client
