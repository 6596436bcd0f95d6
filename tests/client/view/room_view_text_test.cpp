// The words in the room view's frames: names under the faces, the last chat
// line as a caption, the built-in font they are drawn with.
#include <algorithm>
#include <cstdint>

#include <gtest/gtest.h>

#include "bitmap_font.hpp"
#include "first_person_layout.hpp"
#include "frame_text.hpp"
#include "head_points.hpp"
#include "pixel_count.hpp"
#include "room_view.hpp"
#include "view_overlay.hpp"

namespace fw::client {
namespace {

TEST(BitmapFont, EveryPrintableCharacterHasItsOwnGlyphAndOthersAreABox) {
  for (char32_t a = 0x21; a <= 0x7E; ++a) {
    const auto& ga = glyph(a);
    EXPECT_NE(ga, (std::array<std::uint8_t, 5>{})) << static_cast<char>(a) << " is not blank";
    for (char32_t b = a + 1; b <= 0x7E; ++b) EXPECT_NE(ga, glyph(b)) << static_cast<char>(a) << " " << static_cast<char>(b);
  }
  EXPECT_EQ(glyph(U'é'), glyph(U'\u4E2D'));
  EXPECT_NE(glyph(U'é'), glyph(U'e'));
}

TEST(BitmapFont, Utf8IsReadAsCharactersAndBrokenBytesAsOneEach) {
  EXPECT_EQ(code_points("Zoë 中"), (std::vector<char32_t>{U'Z', U'o', U'ë', U' ', U'中'}));
  EXPECT_EQ(code_points("a\xC3"), (std::vector<char32_t>{U'a', 0xFFFD}));
  EXPECT_EQ(code_points("\xFF\x80x").size(), 3u);
}

TEST(FrameText, LongTextIsCutWithAnEllipsisAtACharacterBoundary) {
  EXPECT_EQ(fit_text("grace", 100, 1), "grace");
  const std::string cut = fit_text("Margaret Hamilton", 60, 1);
  EXPECT_LE(text_width(cut, 1), 60);
  EXPECT_EQ(cut.substr(cut.size() - 3), "...");
  EXPECT_EQ(fit_text("ëëëëëëëëëë", 24, 1), "ë...") << "four characters of six pixels";
  EXPECT_EQ(text_width("ab", 2), 22);
}

TEST(FrameText, LettersAreLightOnADarkOutline) {
  model::RgbaImage image(40, 20);
  draw_text(image, 2, 2, "Hi", 1, {250, 250, 250});
  int light = 0, dark_next_to_light = 0;
  for (int y = 1; y < 19; ++y)
    for (int x = 1; x < 39; ++x) {
      if (image.at(x, y)[0] != 250) continue;
      ++light;
      if (image.at(x - 1, y)[0] == 16 || image.at(x + 1, y)[0] == 16) ++dark_next_to_light;
    }
  EXPECT_GT(light, 15);
  EXPECT_GT(dark_next_to_light, 5);
}

// Pixels of the name colour (light grey letters) in `box`.
int letter_pixels(const model::RgbaImage& image, int x0, int y0, int x1, int y1) {
  return fw::test::count_pixels(
      image, [](const std::uint8_t* p) { return p[0] > 225 && p[1] > 225 && p[2] > 225; }, {x0, y0, x1, y1});
}

class RoomViewText : public ::testing::Test {
 protected:
  void SetUp() override {
    render::RendererOptions options;
    options.width = 640;
    options.height = 360;
    options.samples = 0;
    std::string error;
    view_ = RoomView::create(options, error);
    ASSERT_TRUE(view_) << error;
    scene_.you = 1;
    scene_.your_name = "me";
    scene_.now = std::chrono::steady_clock::now();
    for (std::uint32_t id = 1; id <= 4; ++id) {
      SceneMember m;
      m.id = id;
      m.name = id == 1 ? "me" : "person" + std::to_string(id);
      m.face = codec::FaceParams{};
      m.attention = {id, codec::AttentionTarget::room, 0};
      scene_.members.push_back(m);
    }
  }
  std::unique_ptr<RoomView> view_;
  RoomScene scene_;
};

// Each face ends under its chin (its neck fades into the background) and
// its name is under it, in the fade, not on the face.
TEST_F(RoomViewText, EachFaceHasItsNameUnderIt) {
  const model::RgbaImage image = view_->render(scene_);
  const FirstPersonLayout layout = first_person_layout(3, 640, 360);
  const glm::vec3 background = render::RendererOptions{}.background * 255.0f;
  for (const glm::mat4& place : layout.places) {
    const auto pixel = [&](glm::vec3 p) {
      return render::project_to_pixel(layout.camera, glm::vec3(place * glm::vec4(p, 1.0f)), 640, 360);
    };
    const glm::vec3 chin = pixel(head_points().chin);
    const int face_height = static_cast<int>(chin.y - pixel(head_points().eye_mid).y);
    const int x = static_cast<int>(chin.x), y = static_cast<int>(chin.y);
    EXPECT_GT(letter_pixels(image, x - 30, y, x + 30, y + face_height / 2 + 8), 20)
        << "a name under the chin at " << x << "," << y;
    EXPECT_LT(letter_pixels(image, x - 30, y - 40, x + 30, y - 20), 5) << "none on the face";
    // Well under the chin the neck has faded out: background, whatever the
    // skin (where the self view is not drawn over it).
    const int below = std::min(359, y + face_height);
    const PixelRect& self = layout.self_tile;
    if (x >= self.x - 1 && x <= self.x + self.width && below >= self.y - 1) continue;
    const std::uint8_t* p = image.at(x, below);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(p[c], background[c], 6.0) << "the neck goes on under the face at " << x << "," << below;
  }
}

TEST_F(RoomViewText, TheCaptionShowsTheLastChatLine) {
  const model::RgbaImage before = view_->render(scene_);
  scene_.caption = "person3: hello there";
  const model::RgbaImage after = view_->render(scene_);
  const PixelRect box = caption_box(after, first_person_layout(3, 640, 360).self_tile);
  int changed = 0;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) changed += before.at(x, y)[0] != after.at(x, y)[0] ? 1 : 0;
  EXPECT_GT(changed, 60) << "the caption's letters";
  int outside = 0;
  for (int y = 0; y < box.y - 2; ++y)
    for (int x = 0; x < 640; ++x) outside += before.at(x, y)[0] != after.at(x, y)[0] ? 1 : 0;
  EXPECT_EQ(outside, 0) << "nothing else changed";
}

}  // namespace
}  // namespace fw::client
