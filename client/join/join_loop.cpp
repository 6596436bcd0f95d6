#include "join_loop.hpp"

#include <thread>

namespace fw::client {

JoinLoop::JoinLoop(const JoinArgs& args, RoomState& state, RoomView* view, FrameOutputs& outputs, std::ostream& log)
    : args_(args),
      state_(state),
      view_(view),
      outputs_(outputs),
      log_(log),
      appearances_(log),
      start_(Clock::now()),
      next_frame_(start_),
      next_line_(start_ + std::chrono::seconds(1)),
      frame_period_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / args.fps))) {}

JoinOutcome JoinLoop::run(const std::atomic<bool>& interrupted) {
  while (step(Clock::now(), interrupted)) wait_for_next_frame();
  return outcome_;
}

// One frame of the loop; false when the loop ends.
bool JoinLoop::step(Clock::time_point now, const std::atomic<bool>& interrupted) {
  if (interrupted) {
    outcome_.interrupted = true;
    return false;
  }
  if (time_is_up(now) || !follow_room(now) || !joined_in_time(now)) return false;
  // Before the welcome the frames show the self view alone (the viewer's own
  // package or photo): they go out, but --frames counts frames in the room.
  if (view_ && !show_frame(now)) return false;
  if (outcome_.ever_joined) ++outcome_.frames;
  return true;
}

bool JoinLoop::time_is_up(Clock::time_point now) const {
  if (args_.seconds > 0 && now - start_ >= std::chrono::duration<double>(args_.seconds)) return true;
  return args_.frames > 0 && outcome_.frames >= args_.frames;
}

// What the session found: a refusal ends the loop; the welcome starts the
// frames. Prints the live line once a second.
bool JoinLoop::follow_room(Clock::time_point now) {
  std::lock_guard lock(state_.mutex);
  if (state_.fatal_error) {
    outcome_.error = *state_.fatal_error;
    outcome_.status = 2;
    return false;
  }
  outcome_.ever_joined = outcome_.ever_joined || state_.joined;
  if (!args_.quiet && now >= next_line_) {
    log_ << state_.stats.live_line(now) << "\n";
    next_line_ += std::chrono::seconds(1);
  }
  return true;
}

bool JoinLoop::joined_in_time(Clock::time_point now) {
  if (outcome_.ever_joined || now - start_ < std::chrono::duration<double>(args_.join_timeout_s)) return true;
  const bool several = args_.url.find(',') != std::string::npos;
  outcome_.error = "could not join room " + args_.room + (several ? " at any of " : " at ") + args_.url + " within " +
                   std::to_string(static_cast<int>(args_.join_timeout_s)) + " s; is " +
                   (several ? "a server" : "the server") + " running there?";
  outcome_.status = 1;
  return false;
}

// Renders the room as it is now (the newest decoded frame,
// extrapolated) and writes the frame to every output; false when one failed.
bool JoinLoop::show_frame(Clock::time_point now) {
  appearances_.load_new(state_, *view_);
  RoomScene scene;
  {
    std::lock_guard lock(state_.mutex);
    scene = state_.scene(now, args_.name);
  }
  if (outputs_.write(view_->render(scene), outcome_.error)) return true;
  outcome_.status = 1;
  return false;
}

void JoinLoop::wait_for_next_frame() {
  next_frame_ += frame_period_;
  if (next_frame_ < Clock::now()) next_frame_ = Clock::now();  // rendering fell behind: do not try to catch up
  std::this_thread::sleep_until(next_frame_);
}

}  // namespace fw::client
