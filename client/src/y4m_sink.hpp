#pragma once
// Room frames as a YUV4MPEG2 stream (4:2:0, BT.601 full range, the
// C420jpeg layout), which ffplay, mpv and ffmpeg read from a file or a
// pipe: `facewire-client join ... --y4m - | ffplay -`.
#include <cstdio>
#include <cstdint>
#include <string>
#include <vector>

#include "frame_sink.hpp"

namespace fw::client {

class Y4mSink : public FrameSink {
 public:
  /// Opens `path` ("-" for stdout) for frames of width x height (both even)
  /// at `fps` frames per second.
  static std::unique_ptr<Y4mSink> create(const std::string& path, int width, int height, int fps, std::string& error);
  ~Y4mSink() override;
  bool write(const model::RgbaImage& frame, std::string& error) override;

 private:
  Y4mSink(std::FILE* file, bool owned, int width, int height) : file_(file), owned_(owned), width_(width), height_(height) {}
  std::FILE* file_;
  bool owned_;
  int width_, height_;
  std::vector<std::uint8_t> planes_;
};

/// The three planes (Y full size, then Cb and Cr at half size each way) of
/// an RGBA image with even width and height; alpha is ignored.
void rgba_to_i420(const model::RgbaImage& image, std::vector<std::uint8_t>& planes);

}  // namespace fw::client
