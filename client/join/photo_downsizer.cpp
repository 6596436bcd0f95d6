#include "photo_downsizer.hpp"

#include <algorithm>
#include <cmath>

#include "fw/render/image_codec.hpp"
#include "fw/render/jpeg_codec.hpp"

namespace fw::client {

model::RgbaImage shrink_to_fit(const model::RgbaImage& image, int max_side) {
  const int longer = std::max(image.width, image.height);
  if (longer <= max_side) return image;
  const double scale = static_cast<double>(max_side) / longer;
  const int width = std::max(1, static_cast<int>(std::lround(image.width * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(image.height * scale)));
  model::RgbaImage out(width, height);
  // Each output pixel averages the source rectangle it covers (with
  // fractional edge weights), i.e. an exact box filter.
  const double sx = static_cast<double>(image.width) / width, sy = static_cast<double>(image.height) / height;
  for (int y = 0; y < height; ++y) {
    const double y0 = y * sy, y1 = (y + 1) * sy;
    for (int x = 0; x < width; ++x) {
      const double x0 = x * sx, x1 = (x + 1) * sx;
      double sum[4] = {0, 0, 0, 0}, total = 0;
      for (int j = static_cast<int>(y0); j < std::min(image.height, static_cast<int>(std::ceil(y1))); ++j) {
        const double wy = std::min(y1, j + 1.0) - std::max(y0, static_cast<double>(j));
        for (int i = static_cast<int>(x0); i < std::min(image.width, static_cast<int>(std::ceil(x1))); ++i) {
          const double w = wy * (std::min(x1, i + 1.0) - std::max(x0, static_cast<double>(i)));
          const std::uint8_t* p = image.at(i, j);
          for (int c = 0; c < 4; ++c) sum[c] += w * p[c];
          total += w;
        }
      }
      std::uint8_t* q = out.at(x, y);
      for (int c = 0; c < 4; ++c) q[c] = static_cast<std::uint8_t>(std::clamp(std::lround(sum[c] / total), 0l, 255l));
    }
  }
  return out;
}

bool downsize_photo(std::span<const std::uint8_t> photo, DownsizedPhoto& out, std::string& error) {
  if (photo.size() > kMaxPhotoFileBytes) {
    error = "the photo file is over " + std::to_string(kMaxPhotoFileBytes >> 20) + " MB; use a smaller photo";
    return false;
  }
  model::RgbaImage image;
  const bool decoded = render::is_jpeg(photo) ? render::decode_jpeg(photo, kMaxPhotoSide, image, error)
                                              : render::decode_image(photo, kMaxPhotoSide, image, error);
  if (!decoded) {
    if (error == "not a WebP or PNG image") error = "not a JPEG, PNG or WebP photo";
    error = "the photo cannot be read: " + error;
    return false;
  }
  image = shrink_to_fit(image, kMaxUploadSide);
  const std::size_t limit = kTargetUploadBytes + kTargetUploadBytes / 10;
  // The best quality that fits (binary search; size grows with quality),
  // shrinking the photo further if even a poor JPEG of it is too large.
  for (int attempt = 0; attempt < 6; ++attempt) {
    int low = 25, high = 92, best = -1;
    std::vector<std::uint8_t> best_bytes, bytes;
    while (low <= high) {
      const int quality = (low + high) / 2;
      if (!render::encode_jpeg(image, quality, bytes, error)) return false;
      if (bytes.size() <= limit) {
        best = quality;
        best_bytes.swap(bytes);
        low = quality + 1;
      } else {
        high = quality - 1;
      }
    }
    if (best >= 0) {
      out.jpeg = std::move(best_bytes);
      out.width = image.width;
      out.height = image.height;
      out.quality = best;
      return true;
    }
    image = shrink_to_fit(image, std::max(64, std::max(image.width, image.height) * 3 / 4));
  }
  error = "the photo does not compress to " + std::to_string(kTargetUploadBytes / 1024) + " KB; use a plainer photo";
  return false;
}

}  // namespace fw::client
