#include "frame_outputs.hpp"

#include "png_sequence_sink.hpp"
#include "window_sink.hpp"
#include "y4m_sink.hpp"

namespace fw::client {
namespace {

// Adds `sink` to the outputs; false when it did not open.
bool add(std::unique_ptr<FrameSink> sink, FrameOutputs& outputs) {
  if (!sink) return false;
  outputs.sinks.push_back(std::move(sink));
  return true;
}

}  // namespace

bool FrameOutputs::write(const model::RgbaImage& frame, std::string& error) {
  bool all = true;
  for (auto& sink : sinks)
    if (!sink->write(frame, error)) all = false;
  return all;
}

bool open_frame_outputs(const JoinArgs& args, int width, int height, FrameOutputs& outputs, std::string& error) {
  if (args.window && !add(WindowSink::create(width, height, "facewire: " + args.room, error), outputs)) return false;
  if (!args.out_dir.empty() && !add(PngSequenceSink::create(args.out_dir, error), outputs)) return false;
  if (!args.y4m.empty()) {
    if (!add(Y4mSink::create(args.y4m, width, height, args.fps, error), outputs)) return false;
    outputs.video_on_stdout = args.y4m == "-";
  }
  return true;
}

}  // namespace fw::client
