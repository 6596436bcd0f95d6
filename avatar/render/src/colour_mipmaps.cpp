#include "colour_mipmaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "fw/model/srgb.hpp"

namespace fw::render {
namespace {

// Linear light (colour) or coverage (alpha) per channel, bottom row first.
struct LinearLevel {
  int width = 0, height = 0;
  std::vector<float> values;  // width * height * 4
};

LinearLevel decode(const model::RgbaImage& srgb) {
  std::array<float, 256> to_linear{};
  for (std::size_t v = 0; v < to_linear.size(); ++v) to_linear[v] = model::linear_from_srgb(static_cast<std::uint8_t>(v));
  LinearLevel level{srgb.width, srgb.height, std::vector<float>(srgb.pixels.size())};
  for (int y = 0; y < srgb.height; ++y) {
    const std::uint8_t* row = srgb.at(0, srgb.height - 1 - y);
    float* out = &level.values[static_cast<std::size_t>(y) * srgb.width * 4];
    for (int i = 0; i < srgb.width * 4; ++i) out[i] = i % 4 == 3 ? row[i] / 255.0f : to_linear[row[i]];
  }
  return level;
}

// Each texel the plain average of the texels of `source` it covers (two by
// two, three where an odd size leaves one over).
LinearLevel halve(const LinearLevel& source) {
  LinearLevel level{std::max(1, source.width / 2), std::max(1, source.height / 2), {}};
  level.values.resize(static_cast<std::size_t>(level.width) * level.height * 4);
  const auto span = [](int i, int from, int to) {
    return std::pair{i * from / to, std::max(i * from / to + 1, (i + 1) * from / to)};
  };
  for (int y = 0; y < level.height; ++y) {
    const auto [y0, y1] = span(y, source.height, level.height);
    for (int x = 0; x < level.width; ++x) {
      const auto [x0, x1] = span(x, source.width, level.width);
      std::array<float, 4> sum{};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += source.values[(static_cast<std::size_t>(sy) * source.width + sx) * 4 + c];
      const float n = static_cast<float>((y1 - y0) * (x1 - x0));
      for (int c = 0; c < 4; ++c) level.values[(static_cast<std::size_t>(y) * level.width + x) * 4 + c] = sum[c] / n;
    }
  }
  return level;
}

MipLevel encode(const LinearLevel& level) {
  MipLevel out{level.width, level.height, std::vector<std::uint8_t>(level.values.size())};
  for (std::size_t i = 0; i < level.values.size(); ++i) {
    const float v = std::clamp(level.values[i], 0.0f, 1.0f);
    out.texels[i] = static_cast<std::uint8_t>(std::lround((i % 4 == 3 ? v : std::sqrt(v)) * 255.0f));
  }
  return out;
}

}  // namespace

std::vector<MipLevel> square_root_light_mipmaps(const model::RgbaImage& srgb) {
  std::vector<MipLevel> levels;
  if (srgb.width <= 0 || srgb.height <= 0) return levels;
  LinearLevel level = decode(srgb);
  levels.push_back(encode(level));
  while (level.width > 1 || level.height > 1) {
    level = halve(level);
    levels.push_back(encode(level));
  }
  return levels;
}

}  // namespace fw::render
