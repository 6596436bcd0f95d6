#include "join_loop.hpp"

#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "server_messages.hpp"

namespace fw::client {
namespace {

using namespace fw::client::test;

// Keeps the size of every frame it is given; fails when told to.
class RecordingSink : public FrameSink {
 public:
  RecordingSink(std::vector<std::pair<int, int>>* sizes, bool fails) : sizes_(sizes), fails_(fails) {}
  bool write(const model::RgbaImage& frame, std::string& error) override {
    sizes_->emplace_back(frame.width, frame.height);
    if (fails_) error = "the player closed the pipe";
    return !fails_;
  }

 private:
  std::vector<std::pair<int, int>>* sizes_;
  bool fails_;
};

class JoinLoopTest : public ::testing::Test {
 protected:
  JoinLoopTest() {
    args_.url = "ws://127.0.0.1:8080/";
    args_.room = "lobby";
    args_.fps = 60;
    args_.quiet = true;
  }
  JoinOutcome run() { return JoinLoop(args_, state_, view_.get(), outputs_, log_).run(interrupted_); }
  void in_the_room() {
    std::lock_guard lock(state_.mutex);
    state_.joined = true;
  }
  // Bob in the room with a decoded face; a renderer and a recording output.
  void with_a_face_and_a_view(bool output_fails = false) {
    {
      std::lock_guard lock(state_.mutex);
      codec::Welcome welcome;
      welcome.you = 1;
      welcome.avatars = {avatar_info(2, "bob")};
      state_.welcomed(welcome, {}, std::chrono::steady_clock::now());
      FaceStream bob;
      state_.decode_room_frame(room_frame({{2, bob.frame(face(0.6f))}}), std::chrono::steady_clock::now());
    }
    render::RendererOptions options;
    options.width = 48;
    options.height = 32;
    options.samples = 0;
    std::string error;
    view_ = RoomView::create(options, error);
    ASSERT_TRUE(view_) << error;
    outputs_.sinks.push_back(std::make_unique<RecordingSink>(&frames_, output_fails));
  }

  JoinArgs args_;
  RoomState state_;
  std::unique_ptr<RoomView> view_;
  FrameOutputs outputs_;
  std::ostringstream log_;
  std::atomic<bool> interrupted_{false};
  std::vector<std::pair<int, int>> frames_;
};

TEST_F(JoinLoopTest, CountsItsFramesOnceInTheRoomAndStopsAtFrames) {
  args_.frames = 3;
  in_the_room();
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 0) << outcome.error;
  EXPECT_TRUE(outcome.ever_joined);
  EXPECT_EQ(outcome.frames, 3);
  EXPECT_FALSE(outcome.interrupted);
}

TEST_F(JoinLoopTest, RendersTheRoomToEveryOutput) {
  args_.frames = 2;
  with_a_face_and_a_view();
  in_the_room();
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 0) << outcome.error;
  EXPECT_EQ(frames_, (std::vector<std::pair<int, int>>{{48, 32}, {48, 32}}));
}

TEST_F(JoinLoopTest, AnOutputThatFailsEndsTheLoopWithStatusOne) {
  args_.frames = 5;
  with_a_face_and_a_view(true);
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 1);
  EXPECT_EQ(outcome.error, "the player closed the pipe");
  EXPECT_EQ(frames_.size(), 1u);
  EXPECT_EQ(outcome.frames, 0);
}

TEST_F(JoinLoopTest, ARefusalEndsItWithStatusTwo) {
  {
    std::lock_guard lock(state_.mutex);
    state_.fatal_error = "the server refused this client: room full (closing code 5)";
  }
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 2);
  EXPECT_EQ(outcome.error, "the server refused this client: room full (closing code 5)");
}

TEST_F(JoinLoopTest, GivesUpWhenNoWelcomeCameInTime) {
  args_.join_timeout_s = 0.05;
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 1);
  EXPECT_FALSE(outcome.ever_joined);
  EXPECT_EQ(outcome.error,
            "could not join room lobby at ws://127.0.0.1:8080/ within 0 s; is the server running there?");
}

TEST_F(JoinLoopTest, StopsWhenInterruptedOrWhenTheSecondsAreUp) {
  interrupted_ = true;
  EXPECT_TRUE(run().interrupted);
  interrupted_ = false;
  args_.seconds = 0.1;
  const auto started = std::chrono::steady_clock::now();
  const JoinOutcome outcome = run();
  EXPECT_EQ(outcome.status, 0);
  EXPECT_FALSE(outcome.interrupted);
  EXPECT_GE(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(100));
}

TEST_F(JoinLoopTest, PrintsTheLinkOnceASecondUnlessQuiet) {
  args_.quiet = false;
  args_.seconds = 1.1;
  run();
  const std::string log = log_.str();
  EXPECT_NE(log.find("kbit/s"), std::string::npos) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
}

}  // namespace
}  // namespace fw::client
