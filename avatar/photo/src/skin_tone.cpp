#include "skin_tone.hpp"

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace fw::photo {

std::array<std::uint8_t, 3> estimate_skin_tone(const cv::Mat& texture,
                                               const std::array<model::Mask, model::kMaskRegionCount>& masks,
                                               int mask_size) {
  cv::Mat small;
  cv::resize(texture, small, cv::Size(mask_size, mask_size), 0, 0, cv::INTER_AREA);
  using R = model::MaskRegion;
  const auto strong = [&](R region, std::size_t i) { return masks[static_cast<std::size_t>(region)][i] > 128; };
  std::array<std::vector<std::uint8_t>, 3> channels;
  for (int y = 0; y < mask_size; ++y)
    for (int x = 0; x < mask_size; ++x) {
      const auto i = static_cast<std::size_t>(y * mask_size + x);
      if (!strong(R::forehead, i) && !strong(R::cheek_left, i) && !strong(R::cheek_right, i)) continue;
      const cv::Vec3b c = small.at<cv::Vec3b>(y, x);
      for (int k = 0; k < 3; ++k) channels[static_cast<std::size_t>(k)].push_back(c[k]);
    }
  std::array<std::uint8_t, 3> rgb{128, 128, 128};
  for (int k = 0; k < 3; ++k) {
    auto& v = channels[static_cast<std::size_t>(k)];
    if (v.empty()) return rgb;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    rgb[static_cast<std::size_t>(2 - k)] = v[v.size() / 2];
  }
  return rgb;
}

}  // namespace fw::photo
