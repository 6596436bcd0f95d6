#include "fw/render/y4m_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

namespace fw::render {
namespace {

std::uint8_t clamp_byte(float value) { return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0l, 255l)); }

}  // namespace

void rgba_to_i420(const model::RgbaImage& image, std::vector<std::uint8_t>& planes) {
  const int w = image.width, h = image.height;
  const std::size_t luma = static_cast<std::size_t>(w) * h, chroma = luma / 4;
  planes.resize(luma + 2 * chroma);
  std::uint8_t* y_plane = planes.data();
  std::uint8_t* cb_plane = y_plane + luma;
  std::uint8_t* cr_plane = cb_plane + chroma;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = image.at(x, y);
      y_plane[static_cast<std::size_t>(y) * w + x] = clamp_byte(0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]);
    }
  // Chroma of each 2x2 block from its mean colour (JPEG/MPEG-1 siting: centred).
  for (int y = 0; y < h / 2; ++y)
    for (int x = 0; x < w / 2; ++x) {
      float r = 0, g = 0, b = 0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const std::uint8_t* p = image.at(2 * x + dx, 2 * y + dy);
          r += p[0];
          g += p[1];
          b += p[2];
        }
      r /= 4;
      g /= 4;
      b /= 4;
      const std::size_t i = static_cast<std::size_t>(y) * (w / 2) + x;
      cb_plane[i] = clamp_byte(128.0f - 0.168736f * r - 0.331264f * g + 0.5f * b);
      cr_plane[i] = clamp_byte(128.0f + 0.5f * r - 0.418688f * g - 0.081312f * b);
    }
}

std::unique_ptr<Y4mWriter> Y4mWriter::create(const std::string& path, int width, int height, int fps,
                                             std::string& error) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    error = "Y4M video (4:2:0) needs an even width and height, not " + std::to_string(width) + "x" +
            std::to_string(height);
    return nullptr;
  }
  const bool to_stdout = path == "-";
  std::FILE* file = to_stdout ? stdout : std::fopen(path.c_str(), "wb");
  if (!file) {
    error = path + ": cannot open for writing (" + std::strerror(errno) + ")";
    return nullptr;
  }
  // XCOLORRANGE=FULL is the extension ffmpeg reads for full-range samples.
  std::fprintf(file, "YUV4MPEG2 W%d H%d F%d:1 Ip A1:1 C420jpeg XCOLORRANGE=FULL\n", width, height, fps);
  return std::unique_ptr<Y4mWriter>(new Y4mWriter(file, !to_stdout, width, height));
}

Y4mWriter::~Y4mWriter() {
  if (owned_) std::fclose(file_);
  else std::fflush(file_);
}

bool Y4mWriter::write(const model::RgbaImage& frame, std::string& error) {
  if (frame.width != width_ || frame.height != height_) {
    error = "a frame of another size than the stream's";
    return false;
  }
  rgba_to_i420(frame, planes_);
  if (std::fputs("FRAME\n", file_) < 0 || std::fwrite(planes_.data(), 1, planes_.size(), file_) != planes_.size() ||
      std::fflush(file_) != 0) {
    error = std::string("writing the Y4M stream failed (") + std::strerror(errno) + "); was the player closed?";
    return false;
  }
  return true;
}

}  // namespace fw::render
