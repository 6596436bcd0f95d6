#pragma once
// Rendered frames as a YUV4MPEG2 stream (4:2:0, BT.601 full range, C420jpeg),
// which ffplay, mpv and ffmpeg read from a file or a pipe.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "fw/model/image.hpp"

namespace fw::server {

class Y4mWriter {
 public:
  /// Opens `path` ("-": stdout) for frames of width x height (both even) at `fps`.
  static std::unique_ptr<Y4mWriter> create(const std::string& path, int width, int height, int fps, std::string& error);
  ~Y4mWriter();
  Y4mWriter(const Y4mWriter&) = delete;
  Y4mWriter& operator=(const Y4mWriter&) = delete;
  bool write(const model::RgbaImage& frame, std::string& error);

 private:
  Y4mWriter(std::FILE* file, bool owned) : file_(file), owned_(owned) {}
  std::FILE* file_;
  bool owned_;
  std::vector<std::uint8_t> planes_;
};

}  // namespace fw::server
