#include "y4m_writer.hpp"

#include <algorithm>
#include <cmath>

namespace fw::server {
namespace {

std::uint8_t clamp_byte(float v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

std::unique_ptr<Y4mWriter> Y4mWriter::create(const std::string& path, int width, int height, int fps, std::string& error) {
  if (width % 2 || height % 2 || width <= 0 || height <= 0) {
    error = "Y4M frames need an even width and height";
    return nullptr;
  }
  std::FILE* file = path == "-" ? stdout : std::fopen(path.c_str(), "wb");
  if (!file) {
    error = "cannot write " + path;
    return nullptr;
  }
  std::unique_ptr<Y4mWriter> w(new Y4mWriter(file, path != "-"));
  std::fprintf(file, "YUV4MPEG2 W%d H%d F%d:1 Ip A1:1 C420jpeg XCOLORRANGE=FULL\n", width, height, fps);
  return w;
}

Y4mWriter::~Y4mWriter() {
  if (owned_) std::fclose(file_);
  else std::fflush(file_);
}

bool Y4mWriter::write(const model::RgbaImage& f, std::string& error) {
  const std::size_t w = static_cast<std::size_t>(f.width), h = static_cast<std::size_t>(f.height);
  planes_.assign(w * h * 3 / 2, 0);
  std::uint8_t* y = planes_.data();
  std::uint8_t* cb = y + w * h;
  std::uint8_t* cr = cb + w * h / 4;
  for (std::size_t row = 0; row < h; ++row)
    for (std::size_t col = 0; col < w; ++col) {
      const std::uint8_t* p = &f.pixels[(row * w + col) * 4];
      y[row * w + col] = clamp_byte(0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]);
    }
  for (std::size_t row = 0; row < h; row += 2)
    for (std::size_t col = 0; col < w; col += 2) {
      float r = 0, g = 0, b = 0;
      for (std::size_t dy = 0; dy < 2; ++dy)
        for (std::size_t dx = 0; dx < 2; ++dx) {
          const std::uint8_t* p = &f.pixels[((row + dy) * w + col + dx) * 4];
          r += p[0] / 4.0f, g += p[1] / 4.0f, b += p[2] / 4.0f;
        }
      const std::size_t i = (row / 2) * (w / 2) + col / 2;
      cb[i] = clamp_byte(128 - 0.168736f * r - 0.331264f * g + 0.5f * b);
      cr[i] = clamp_byte(128 + 0.5f * r - 0.418688f * g - 0.081312f * b);
    }
  if (std::fputs("FRAME\n", file_) < 0 || std::fwrite(planes_.data(), 1, planes_.size(), file_) != planes_.size()) {
    error = "writing the Y4M stream failed";
    return false;
  }
  return true;
}

}  // namespace fw::server
