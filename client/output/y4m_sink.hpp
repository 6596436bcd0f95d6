#pragma once
// Room frames as a YUV4MPEG2 stream for ffplay, mpv or ffmpeg:
// `facewire-client join ... --y4m - | ffplay -`.
#include <memory>
#include <string>

#include "fw/render/y4m_writer.hpp"
#include "frame_sink.hpp"

namespace fw::client {

class Y4mSink : public FrameSink {
 public:
  /// Opens `path` ("-" for stdout) for frames of width x height at `fps`;
  /// the error names the flag to change.
  static std::unique_ptr<Y4mSink> create(const std::string& path, int width, int height, int fps, std::string& error);
  bool write(const model::RgbaImage& frame, std::string& error) override { return writer_->write(frame, error); }

 private:
  explicit Y4mSink(std::unique_ptr<render::Y4mWriter> writer) : writer_(std::move(writer)) {}
  std::unique_ptr<render::Y4mWriter> writer_;
};

}  // namespace fw::client
