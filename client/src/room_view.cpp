#include "room_view.hpp"

#include <stdexcept>

#include "fw/model/face_reconstruction.hpp"
#include "room_layout.hpp"

namespace fw::client {

std::unique_ptr<RoomView> RoomView::create(const render::RendererOptions& options, std::string& error) {
  std::unique_ptr<RoomView> view(new RoomView(options));
  if (!view->restart_renderer(error)) return nullptr;
  // A muted generic face stands in for avatars whose package is on its way.
  model::Appearance look;
  look.skin = {0.70f, 0.66f, 0.64f};
  look.hair = {0.30f, 0.30f, 0.32f};
  view->placeholder_ = std::make_shared<render::AvatarAppearance>(render::generic_appearance(look));
  return view;
}

bool RoomView::restart_renderer(std::string& error) {
  renderer_.reset();  // one GL context at a time
  renderer_ = render::FaceRenderer::create(options_, error);
  if (!renderer_) return false;
  retired_faces_ = 0;
  for (auto& [id, shown] : shown_) shown.uploaded = false;
  return true;
}

void RoomView::upload(Shown& shown) {
  const auto& appearance = shown.appearance ? *shown.appearance : *placeholder_;
  shown.face = renderer_->add_face(appearance.avatar.face, appearance.textures);
  shown.uploaded = true;
}

void RoomView::set_appearance(std::uint32_t avatar, std::shared_ptr<const render::AvatarAppearance> appearance) {
  Shown& shown = shown_[avatar];
  if (shown.uploaded) ++retired_faces_;
  shown.appearance = std::move(appearance);
  shown.uploaded = false;
}

void RoomView::forget(std::uint32_t avatar) {
  const auto it = shown_.find(avatar);
  if (it == shown_.end()) return;
  if (it->second.uploaded) ++retired_faces_;
  shown_.erase(it);
}

model::RgbaImage RoomView::render(const std::vector<AvatarFace>& faces) {
  std::vector<std::uint32_t> gone;
  for (const auto& [id, shown] : shown_) {
    bool present = false;
    for (const AvatarFace& face : faces) present = present || face.avatar == id;
    if (!present) gone.push_back(id);
  }
  for (const std::uint32_t id : gone) forget(id);
  if (retired_faces_ > kMaxRetiredFaces) {
    std::string error;
    if (!restart_renderer(error)) throw std::runtime_error("the renderer could not restart: " + error);
  }

  const int count = static_cast<int>(faces.size());
  const std::vector<glm::mat4> places = room_places(count);
  std::vector<render::FaceDraw> draws;
  draws.reserve(faces.size());
  for (int i = 0; i < count; ++i) {
    const AvatarFace& face = faces[static_cast<std::size_t>(i)];
    Shown& shown = shown_[face.avatar];
    if (!shown.uploaded) upload(shown);
    const auto& appearance = shown.appearance ? *shown.appearance : *placeholder_;
    const model::FaceShape shape = model::reconstruct_face(appearance.avatar, face.params);
    renderer_->set_face_shape(shown.face, shape.positions, shape.uvs);
    draws.push_back(render::face_draw(shown.face, face.params, places[static_cast<std::size_t>(i)]));
  }
  const auto camera = room_camera(count, static_cast<float>(options_.width) / static_cast<float>(options_.height));
  return renderer_->render(draws, camera);
}

}  // namespace fw::client
