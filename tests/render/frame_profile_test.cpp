#include "fw/render/frame_profile.hpp"

#include <gtest/gtest.h>

#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::render {
namespace {

TEST(FrameProfile, AddsEachPartAndVariantAndDividesByTheFrames) {
  FrameProfile profile;
  EXPECT_TRUE(profile.per_frame_ms(false).empty());
  profile.add("skin", "plain+albedo", 0.004);
  profile.add("shell", "matte+albedo", 0.002);
  profile.add("skin", "plain+albedo", 0.002);
  profile.add("resolve", "", 0.001);
  EXPECT_TRUE(profile.per_frame_ms(false).empty());  // no frame yet
  profile.frames = 2;
  const auto parts = profile.per_frame_ms(false);
  EXPECT_DOUBLE_EQ(parts.at("skin"), 3.0);
  EXPECT_DOUBLE_EQ(parts.at("shell"), 1.0);
  EXPECT_DOUBLE_EQ(parts.at("resolve"), 0.5);
  const auto variants = profile.per_frame_ms(true);
  EXPECT_EQ(variants.size(), 2u);  // the resolve runs no variant
  EXPECT_DOUBLE_EQ(variants.at("plain+albedo"), 3.0);
}

TEST(FrameProfile, ARendererFillsEveryPartOfAFrame) {
  std::string error;
  RendererOptions options;
  options.width = options.height = 64;
  auto renderer = FaceRenderer::create(options, error);
  ASSERT_TRUE(renderer) << error;
  const AvatarAppearance appearance = generic_appearance(model::Appearance{});
  const FaceId id = renderer->add_face(model::generic_face(), appearance.textures);
  FrameProfile profile;
  renderer->set_profile(&profile);
  const FaceDraw draw{id, glm::mat4(1.0f), {}};
  renderer->render(std::span(&draw, 1), Camera::group(1, 1.0f));
  renderer->set_profile(nullptr);
  renderer->render(std::span(&draw, 1), Camera::group(1, 1.0f));  // not counted
  EXPECT_EQ(profile.frames, 1);
  for (const char* part : {"background", "clear", "skin", "eyes", "mouth", "shell", "resolve", "readback"})
    EXPECT_TRUE(profile.part_seconds.contains(part)) << part;
  for (const char* variant : {"plain+albedo", "eye+albedo", "matte+albedo"})
    EXPECT_TRUE(profile.variant_seconds.contains(variant)) << variant;
}

}  // namespace
}  // namespace fw::render
