#include "prep_preview.hpp"

#include "fw/render/avatar_appearance.hpp"
#include "fw/render/contact_sheet.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/image_ops.hpp"

namespace fw::server {
namespace {

constexpr int kPanel = 320;
const glm::u8vec3 kLandmarkColour{60, 255, 90};

}  // namespace

bool make_prep_preview(const photo::PreparedAvatar& avatar, model::RgbaImage& sheet, std::string& error) {
  constexpr int kSheetPanel = 3 * kPanel / render::kSheetColumns;
  render::AvatarAppearance appearance;
  if (!render::load_avatar_appearance(avatar.package, appearance, error)) return false;
  render::RendererOptions options;
  options.width = options.height = kPanel;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) return false;
  const model::GenericFace& face = appearance.avatar.face;
  const render::FaceId id = renderer->add_face(face, appearance.textures);
  const render::Camera camera = render::Camera::portrait(1.0f);

  // Below the three large panels, the contact sheet: every expression,
  // gaze, a blink, blush and pallor, the head turned.
  model::RgbaImage expressions;
  if (!render::render_contact_sheet(appearance, kSheetPanel, render::kSheetColumns, expressions, error)) return false;
  sheet = model::RgbaImage(3 * kPanel, kPanel + expressions.height);
  for (std::size_t i = 3; i < sheet.pixels.size(); i += 4) sheet.pixels[i] = 255;
  render::paste(sheet, expressions, 0, kPanel);
  // 1: the aligned texture with the landmarks it was aligned by.
  model::RgbaImage texture = render::resized(avatar.report.face_texture, kPanel, kPanel);
  const model::TextureFrame& frame = face.texture_frame;
  for (const glm::vec2& p : avatar.package.landmarks) {
    const glm::vec2 uv = frame.to_uv(p);
    render::draw_dot(texture, {uv.x * kPanel, (1.0f - uv.y) * kPanel}, 2.0f, kLandmarkColour);
  }
  render::paste(sheet, texture, 0, 0);

  // 2: the avatar, neutral, with the fitted face's landmark vertices.
  const render::FaceDraw neutral{id, render::head_transform({}), {}};
  model::RgbaImage front = renderer->render({&neutral, 1}, camera);
  for (std::uint32_t v : face.landmark_vertices) {
    const glm::vec3 px = render::project_to_pixel(camera, face.skin.positions[v], kPanel, kPanel);
    render::draw_dot(front, {px.x, px.y}, 1.6f, kLandmarkColour);
  }
  render::paste(sheet, front, kPanel, 0);

  // 3: turned, to show the face on the generic head's depth.
  render::HeadPose pose;
  pose.yaw_rad = 0.45f;
  const render::FaceDraw turned{id, render::head_transform(pose), {}};
  render::paste(sheet, renderer->render({&turned, 1}, camera), 2 * kPanel, 0);
  return true;
}

}  // namespace fw::server
