#include "fw/render/contact_sheet.hpp"

#include <string>

#include "fw/model/expressions.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/render/image_ops.hpp"

namespace fw::render {

std::vector<SheetPanel> sheet_panels() {
  std::vector<SheetPanel> panels{{"neutral", {}}};
  for (std::size_t e = 0; e < model::kExpressionCount; ++e) {
    SheetPanel panel{std::string(model::kExpressionNames[e]), {}};
    model::apply_expression(static_cast<model::Expression>(e), 1.0f, panel.params);
    panels.push_back(panel);
  }
  const auto gaze = [](const char* name, float yaw, float pitch) {
    SheetPanel panel{name, {}};
    panel.params.eye_left = panel.params.eye_right = {yaw, pitch};
    return panel;
  };
  panels.push_back(gaze("gaze left", 0.45f, 0.0f));
  panels.push_back(gaze("gaze right", -0.45f, 0.0f));
  panels.push_back(gaze("gaze up", 0.0f, 0.3f));
  SheetPanel blink{"blink", {}};
  blink.params.lid_left = blink.params.lid_right = 1.0f;
  panels.push_back(blink);
  SheetPanel blush{"blush", {}};
  blush.params.blush = {0.4f, 1.0f, 1.0f, 0.5f, 0.8f};
  panels.push_back(blush);
  SheetPanel pallor{"pallor", {}};
  pallor.params.pallor = 1.0f;
  panels.push_back(pallor);
  // Turned, the head shows whether it is a head or the edge of a mask.
  for (const int degrees : {30, 60}) {
    SheetPanel turned{"turned " + std::to_string(degrees), {}};
    turned.params.head_yaw_rad = static_cast<float>(degrees) * 0.017453293f;
    panels.push_back(turned);
  }
  return panels;
}

bool render_contact_sheet(const AvatarAppearance& appearance, int panel_size, int columns, model::RgbaImage& sheet,
                          std::string& error) {
  RendererOptions options;
  options.width = options.height = panel_size;
  auto renderer = FaceRenderer::create(options, error);
  if (!renderer) return false;
  const FaceId id = renderer->add_face(appearance.avatar.face, appearance.textures);
  const Camera camera = Camera::portrait(1.0f);
  const std::vector<SheetPanel> panels = sheet_panels();
  const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
  sheet = model::RgbaImage(columns * panel_size, rows * panel_size);
  // Cells past the last panel show the panels' background, not a hole.
  const glm::vec3 background = options.background * 255.0f + 0.5f;
  for (std::size_t i = 0; i < sheet.pixels.size(); i += 4) {
    for (int c = 0; c < 3; ++c) sheet.pixels[i + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(background[c]);
    sheet.pixels[i + 3] = 255;
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const model::FaceShape shape = model::reconstruct_face(appearance.avatar, panels[i].params);
    renderer->set_face_shape(id, shape.positions, shape.uvs);
    const FaceDraw draw = face_draw(id, panels[i].params);
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    paste(sheet, renderer->render({&draw, 1}, camera), column * panel_size, row * panel_size);
  }
  return true;
}

}  // namespace fw::render
