// The start page's WebGL2 preview, in a real (headless) Chromium against a
// real server: proves the shared GLSL ES 3.00 shaders and the asset load in
// a browser as they do in the native renderer.
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>
#include <png.h>

#include "headless_browser.hpp"
#include "server_process.hpp"

namespace fw::web {
namespace {

class FacePreviewTest : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(data_); }
  void SetUp() override {
    if (!std::filesystem::exists(test::kChromium)) GTEST_FAIL() << "chromium is missing: run deploy/install-deps.sh";
    ASSERT_GT(server_.port(), 0);
    url_ = "http://127.0.0.1:" + std::to_string(server_.port()) + "/";
  }
  // Its own data directory: tests running at once never share one.
  const std::string data_ = (std::filesystem::temp_directory_path() /
                             ("fw-preview-" + std::to_string(::getpid()) + "-" + std::to_string(counter_++)))
                                .string();
  test::ServerProcess server_{test::bin("facewire-server"), "--no-demo-room --data " + data_};
  static inline int counter_ = 0;
  std::string url_;
};

TEST_F(FacePreviewTest, ShadersCompileAndTheFaceIsDrawn) {
  const auto dom = test::headless_chromium(url_, "--dump-dom");
  ASSERT_EQ(dom.status, 0) << dom.output;
  EXPECT_EQ(dom.output.find("<p id=\"status\">cannot draw"), std::string::npos) << dom.output;
  EXPECT_NE(dom.output.find("drawn with the shared shaders"), std::string::npos) << dom.output;
  EXPECT_NE(dom.output.find("data-frames=\""), std::string::npos) << "no frame was drawn";
}

TEST_F(FacePreviewTest, ScreenshotShowsSkin) {
  const auto shot = std::filesystem::temp_directory_path() / ("facewire-preview-" + std::to_string(::getpid()) + ".png");
  const auto result = test::headless_chromium(url_, "--screenshot=" + shot.string());
  ASSERT_EQ(result.status, 0) << result.output;
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, shot.c_str())) << "no screenshot";
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr));
  std::filesystem::remove(shot);
  // The page is dark blue-grey; only the rendered face is warm and light.
  std::size_t skin = 0;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3)
    skin += pixels[i] > 150 && pixels[i] > pixels[i + 2] + 40 && pixels[i + 1] > 90;
  EXPECT_GT(skin, 30000u) << "the face covers about a fifth of the 360x360 canvas";
}

}  // namespace
}  // namespace fw::web
