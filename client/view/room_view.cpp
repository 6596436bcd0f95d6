#include "room_view.hpp"

#include <algorithm>
#include <stdexcept>

#include "fw/model/face_reconstruction.hpp"
#include "head_points.hpp"
#include "view_overlay.hpp"
#include "view_plan.hpp"

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
  self_.uploaded = false;
  return true;
}

const render::AvatarAppearance& RoomView::appearance_of(const Shown& shown) const {
  return shown.appearance ? *shown.appearance : *placeholder_;
}

void RoomView::upload(Shown& shown) {
  const auto& appearance = appearance_of(shown);
  shown.face = renderer_->add_face(appearance.avatar.face, appearance.textures);
  shown.uploaded = true;
}

void RoomView::set_appearance(std::uint32_t avatar, std::shared_ptr<const render::AvatarAppearance> appearance) {
  Shown& shown = shown_[avatar];
  if (shown.uploaded) ++retired_faces_;
  shown.appearance = std::move(appearance);
  shown.uploaded = false;
}

void RoomView::set_self_look(std::shared_ptr<const render::AvatarAppearance> appearance, model::RgbaImage photo) {
  self_appearance_ = std::move(appearance);
  self_photo_ = std::move(photo);
}

void RoomView::forget(std::uint32_t avatar) {
  const auto it = shown_.find(avatar);
  if (it == shown_.end()) return;
  if (it->second.uploaded) ++retired_faces_;
  shown_.erase(it);
}

void RoomView::forget_absent(const RoomScene& scene) {
  std::vector<std::uint32_t> gone;
  for (const auto& [id, shown] : shown_) {
    const bool present = std::any_of(scene.members.begin(), scene.members.end(),
                                     [id = id](const SceneMember& m) { return m.id == id; });
    if (!present) gone.push_back(id);
  }
  for (const std::uint32_t id : gone) forget(id);
  if (retired_faces_ > kMaxRetiredFaces) {
    std::string error;
    if (!restart_renderer(error)) throw std::runtime_error("the renderer could not restart: " + error);
  }
}

render::FaceDraw RoomView::draw_of(Shown& shown, const codec::FaceParams& params, const glm::mat4& place) {
  if (!shown.uploaded) upload(shown);
  const model::FaceShape shape = model::reconstruct_face(appearance_of(shown).avatar, params);
  renderer_->set_face_shape(shown.face, shape.positions, shape.uvs);
  return render::face_draw(shown.face, params, place);
}

RoomView::Shown* RoomView::self_face(const RoomScene& scene) {
  // The own avatar's package once the room has it; before that the package
  // this client brought, else its photo (drawn flat), else the stand-in.
  std::shared_ptr<const render::AvatarAppearance> look;
  if (const auto it = shown_.find(scene.you); scene.you != 0 && it != shown_.end() && it->second.appearance)
    look = it->second.appearance;
  else if (self_appearance_)
    look = self_appearance_;
  else if (self_photo_.width > 0)
    return nullptr;
  if (self_.uploaded && self_.appearance != look) {
    ++retired_faces_;
    self_.uploaded = false;
  }
  self_.appearance = std::move(look);
  return &self_;
}

model::RgbaImage RoomView::render(const RoomScene& scene) {
  forget_absent(scene);
  const ViewPlan plan = plan_view(scene, options_.width, options_.height, blends_);
  std::vector<render::FaceDraw> draws;
  draws.reserve(plan.others.size());
  for (const PlacedFace& face : plan.others) draws.push_back(draw_of(shown_[face.id], face.params, face.place));
  model::RgbaImage image = renderer_->render(draws, plan.layout.camera);
  for (const PlacedFace& face : plan.others) fade_neck(image, plan.layout.camera, face.place, options_.background);

  // The self view is a picture of its own: drawn alone (nobody's neck
  // behind it) and copied into its tile.
  if (Shown* self = self_face(scene)) {
    const render::FaceDraw own = draw_of(*self, plan.self_params, plan.layout.self_place);
    copy_tile(renderer_->render({&own, 1}, plan.layout.camera), plan.layout.self_tile, image);
  } else {
    draw_photo_in_tile(image, self_photo_, plan.layout.self_tile);
  }
  draw_self_tile(image, plan.layout.self_tile, scene.your_name);
  for (const PlacedFace& face : plan.others) draw_name_under(image, plan.layout.camera, face.place, face.name);
  draw_caption(image, plan.layout.self_tile, scene.caption);
  return image;
}

}  // namespace fw::client
