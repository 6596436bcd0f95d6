#pragma once
// A package's avatar in a renderer of its own, ready to draw: for the photo
// tests that look at what a prepared avatar shows.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "fw/model/avatar_package.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::photo {

struct RenderedAvatar {
  render::AvatarAppearance appearance;
  std::unique_ptr<render::FaceRenderer> renderer;
  render::FaceId id = 0;

  RenderedAvatar(const model::AvatarPackage& package, int size, glm::vec3 background) {
    std::string error;
    EXPECT_TRUE(render::load_avatar_appearance(package, appearance, error)) << error;
    render::RendererOptions options;
    options.width = options.height = size;
    options.background = background;
    renderer = render::FaceRenderer::create(options, error);
    id = renderer->add_face(appearance.avatar.face, appearance.textures);
  }
  model::RgbaImage draw(const render::FaceDraw& d) { return renderer->render({&d, 1}, render::Camera::portrait(1.0f)); }
};

}  // namespace fw::photo
