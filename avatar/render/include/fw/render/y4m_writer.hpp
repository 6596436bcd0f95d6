#pragma once
// Rendered frames as a YUV4MPEG2 stream (4:2:0, BT.601 full range, the
// C420jpeg layout), which ffplay, mpv and ffmpeg read from a file or a pipe.
// The client's --y4m and the server's render-scene both write through it.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "fw/model/image.hpp"

namespace fw::render {

class Y4mWriter {
 public:
  /// Opens `path` ("-" for stdout) for frames of width x height (both even,
  /// as 4:2:0 needs) at `fps` frames per second and writes the stream header.
  static std::unique_ptr<Y4mWriter> create(const std::string& path, int width, int height, int fps,
                                           std::string& error);
  ~Y4mWriter();
  Y4mWriter(const Y4mWriter&) = delete;
  Y4mWriter& operator=(const Y4mWriter&) = delete;

  /// Appends one frame of the stream's size and flushes it, so a player on a
  /// pipe shows it at once.
  bool write(const model::RgbaImage& frame, std::string& error);

 private:
  Y4mWriter(std::FILE* file, bool owned, int width, int height)
      : file_(file), owned_(owned), width_(width), height_(height) {}
  std::FILE* file_;
  bool owned_;
  int width_, height_;
  std::vector<std::uint8_t> planes_;
};

/// The three planes (Y full size, then Cb and Cr at half size each way) of
/// an RGBA image with even width and height; alpha is ignored.
void rgba_to_i420(const model::RgbaImage& image, std::vector<std::uint8_t>& planes);

}  // namespace fw::render
