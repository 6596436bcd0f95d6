#pragma once
// The render loop of `join`, on the main thread while the session runs on
// its own (session_thread.hpp): --fps times a second it checks whether to
// stop (Ctrl-C, --frames, --seconds, a refusal, no welcome in time), prints
// the live statistics line, and renders the room (every avatar's newest
// face; before the welcome the self view alone) and writes the frame to
// every output. A frame that takes too
// long is not caught up on: the next one is drawn from the state of then.
#include <atomic>
#include <chrono>
#include <memory>
#include <ostream>
#include <string>

#include "appearance_loader.hpp"
#include "frame_outputs.hpp"
#include "join_arguments.hpp"
#include "room_state.hpp"
#include "room_view.hpp"

namespace fw::client {

/// How the loop ended.
struct JoinOutcome {
  int status = 0;            ///< 0; 1 never got in, or an output failed; 2 the server refused the client
  std::string error;         ///< what went wrong, for the person
  bool interrupted = false;  ///< Ctrl-C (or SIGTERM)
  bool ever_joined = false;
  int frames = 0;            ///< loop frames since the first welcome (rendered when there is a view)
};

class JoinLoop {
 public:
  using Clock = std::chrono::steady_clock;

  /// `view` may be null (no outputs: the client only receives and
  /// measures); the live line and problems go to `log`.
  JoinLoop(const JoinArgs& args, RoomState& state, RoomView* view, FrameOutputs& outputs, std::ostream& log);

  /// Runs until the loop ends; `interrupted` is looked at every frame.
  JoinOutcome run(const std::atomic<bool>& interrupted);

 private:
  bool step(Clock::time_point now, const std::atomic<bool>& interrupted);
  bool time_is_up(Clock::time_point now) const;
  bool follow_room(Clock::time_point now);
  bool joined_in_time(Clock::time_point now);
  bool show_frame(Clock::time_point now);
  void wait_for_next_frame();

  const JoinArgs& args_;
  RoomState& state_;
  RoomView* view_;
  FrameOutputs& outputs_;
  std::ostream& log_;
  AppearanceLoader appearances_;
  JoinOutcome outcome_;
  Clock::time_point start_, next_frame_, next_line_;
  Clock::duration frame_period_;
};

}  // namespace fw::client
