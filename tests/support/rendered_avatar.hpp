#pragma once
// A package's avatar in a renderer of its own, ready to draw, and its
// renders as OpenCV images: for tests that look at an avatar as a person
// (or dlib) would.
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "fw/model/face_reconstruction.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::test {

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
  /// The face with `params`: its shape (expressions, lids) and its draw.
  model::RgbaImage draw(const codec::FaceParams& params) {
    const model::FaceShape shape = model::reconstruct_face(appearance.avatar, params);
    renderer->set_face_shape(id, shape.positions, shape.uvs);
    return draw(render::face_draw(id, params));
  }
};

inline cv::Mat to_bgr(const model::RgbaImage& image) {
  cv::Mat bgr;
  cv::cvtColor(cv::Mat(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.pixels.data())), bgr,
               cv::COLOR_RGBA2BGR);
  return bgr;
}

}  // namespace fw::test
