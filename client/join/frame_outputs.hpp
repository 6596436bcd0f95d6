#pragma once
// Where `join` sends the room's frames: every sink the command line asked
// for (--window, --out DIR, --y4m FILE|-), opened before the session starts
// so that a sink that cannot open ends the command before it joins.
#include <memory>
#include <string>
#include <vector>

#include "frame_sink.hpp"
#include "join_arguments.hpp"

namespace fw::client {

struct FrameOutputs {
  std::vector<std::unique_ptr<FrameSink>> sinks;
  /// --y4m -: the video owns stdout, so the --json summary goes to stderr.
  bool video_on_stdout = false;

  bool empty() const { return sinks.empty(); }
  /// Writes `frame` to every sink; false and `error` when one failed (the
  /// others still got the frame).
  bool write(const model::RgbaImage& frame, std::string& error);
};

/// Opens the sinks of `args` for frames of width x height; false and
/// `error` when one cannot open (no display, a directory that cannot be made).
bool open_frame_outputs(const JoinArgs& args, int width, int height, FrameOutputs& outputs, std::string& error);

}  // namespace fw::client
