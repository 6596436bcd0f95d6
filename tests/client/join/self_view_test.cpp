// The self view shows from the first frame, before the server said anything.
#include "self_view.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "first_person_layout.hpp"
#include "fw/render/jpeg_codec.hpp"
#include "join_loop.hpp"
#include "pixel_count.hpp"

namespace fw::client {
namespace {

class KeepingSink : public FrameSink {
 public:
  explicit KeepingSink(std::vector<model::RgbaImage>* frames) : frames_(frames) {}
  bool write(const model::RgbaImage& frame, std::string&) override {
    frames_->push_back(frame);
    return true;
  }

 private:
  std::vector<model::RgbaImage>* frames_;
};

// The self view's tile in an image of that size.
fw::test::PixelBox tile_box(int width, int height) {
  const PixelRect tile = first_person_layout(0, width, height).self_tile;
  return {tile.x, tile.y, tile.x + tile.width, tile.y + tile.height};
}

// How many pixels of the self view's tile are near `rgb`.
int tile_pixels_near(const model::RgbaImage& image, std::array<int, 3> rgb) {
  return fw::test::count_pixels(
      image,
      [&](const std::uint8_t* p) {
        return std::abs(p[0] - rgb[0]) + std::abs(p[1] - rgb[1]) + std::abs(p[2] - rgb[2]) < 40;
      },
      tile_box(image.width, image.height));
}

class SelfView : public ::testing::Test {
 protected:
  void SetUp() override {
    render::RendererOptions options;
    options.width = 320;
    options.height = 180;
    options.samples = 0;
    std::string error;
    view_ = RoomView::create(options, error);
    ASSERT_TRUE(view_) << error;
    outputs_.sinks.push_back(std::make_unique<KeepingSink>(&frames_));
  }
  // A photo of one colour, as own_avatar would have downsized it.
  OwnAvatar photo_of(std::array<std::uint8_t, 3> rgb) {
    model::RgbaImage photo(64, 80);
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 64; ++x) std::copy_n(rgb.data(), 3, photo.at(x, y)), photo.at(x, y)[3] = 255;
    OwnAvatar own;
    std::string error;
    EXPECT_TRUE(render::encode_jpeg(photo, 90, own.photo, error)) << error;
    return own;
  }
  std::unique_ptr<RoomView> view_;
  FrameOutputs outputs_;
  std::vector<model::RgbaImage> frames_;
};

TEST_F(SelfView, TheFirstFrameShowsTheOwnPhotoBeforeAnythingArrived) {
  std::string error;
  ASSERT_TRUE(set_self_look(*view_, photo_of({220, 40, 200}), error)) << error;
  ASSERT_TRUE(show_self_view(*view_, outputs_, "me", error)) << error;
  ASSERT_EQ(frames_.size(), 1u);
  const PixelRect tile = first_person_layout(0, 320, 180).self_tile;
  EXPECT_GT(tile_pixels_near(frames_[0], {220, 40, 200}), tile.width * tile.height / 2);
}

TEST_F(SelfView, TheJoinLoopDrawsTheSelfViewWhileItWaitsForTheWelcome) {
  // The own package's face (here the generic face in a colour of its own).
  model::Appearance look;
  look.skin = {0.1f, 0.8f, 0.2f};
  view_->set_self_look(std::make_shared<render::AvatarAppearance>(render::generic_appearance(look)), {});
  JoinArgs args;
  args.url = "ws://127.0.0.1:8080/";
  args.room = "lobby";
  args.name = "me";
  args.fps = 30;
  args.quiet = true;
  args.join_timeout_s = 1.5;  // no server: it gives up, having drawn while it waited
  RoomState state;
  std::ostringstream log;
  std::atomic<bool> interrupted{false};
  const JoinOutcome outcome = JoinLoop(args, state, view_.get(), outputs_, log).run(interrupted);
  EXPECT_FALSE(outcome.ever_joined);
  EXPECT_EQ(outcome.frames, 0) << "--frames counts frames in the room only";
  ASSERT_GE(frames_.size(), 1u) << "the first step draws before it looks at the time";
  // Greenish skin fills a good part of the tile in the very first frame.
  const PixelRect tile = first_person_layout(0, 320, 180).self_tile;
  const int green = fw::test::count_pixels(
      frames_[0], [](const std::uint8_t* p) { return p[1] > p[0] + 30 && p[1] > p[2] + 30; }, tile_box(320, 180));
  EXPECT_GT(green, tile.width * tile.height / 6);
}

}  // namespace
}  // namespace fw::client
