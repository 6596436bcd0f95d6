#include "fw/physics/au_projection.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fw::physics {

namespace {
constexpr std::size_t kC = codec::kAuChannelCount;
}  // namespace

AuBasis AuBasis::from_rows(std::span<const float> rows, std::size_t length) {
  assert(rows.size() == kC * length);
  AuBasis b;
  b.length = length;
  b.rows.resize(kC * length);
  for (std::size_t c = 0; c < kC; ++c) {
    float peak = 0.0f;
    for (std::size_t k = 0; k < length; ++k) peak = std::max(peak, std::abs(rows[c * length + k]));
    b.scale[c] = peak > 0.0f ? peak / 32767.0f : 0.0f;
    for (std::size_t k = 0; k < length; ++k)
      b.rows[c * length + k] =
          peak > 0.0f ? static_cast<std::int16_t>(std::lround(rows[c * length + k] / b.scale[c])) : std::int16_t{0};
  }
  b.gram.assign(kC * kC, 0.0);
  for (std::size_t i = 0; i < kC; ++i)
    for (std::size_t j = 0; j < kC; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < length; ++k) sum += double(b.at(i, k)) * b.at(j, k);
      b.gram[i * kC + j] = sum;
    }
  return b;
}

double project_onto_basis(const AuBasis& basis, std::span<const float> displacement,
                          std::array<float, kC>& weights, int sweeps) {
  const std::size_t n = displacement.size();
  assert(basis.length == n && basis.gram.size() == kC * kC);
  std::array<double, kC> b{};
  for (std::size_t c = 0; c < kC; ++c) {
    const std::int16_t* row = basis.rows.data() + c * n;
    // Eight float lanes summed apart, so the compiler can vectorise without
    // reassociating a single sum; n is a few hundred.
    float lanes[8] = {};
    std::size_t k = 0;
    for (; k + 8 <= n; k += 8)
      for (std::size_t j = 0; j < 8; ++j) lanes[j] += static_cast<float>(row[k + j]) * displacement[k + j];
    float sum = 0.0f;
    for (; k < n; ++k) sum += static_cast<float>(row[k]) * displacement[k];
    for (float lane : lanes) sum += lane;
    b[c] = double(sum) * basis.scale[c];
  }
  double dd = 0.0;
  for (float d : displacement) dd += double(d) * d;
  const std::vector<double>& gram = basis.gram;
  std::array<double, kC> w{};
  for (std::size_t c = 0; c < kC; ++c) w[c] = std::clamp(double(weights[c]), 0.0, 1.0);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    double largest_step = 0.0;  // warm-started, a few sweeps usually do
    for (std::size_t c = 0; c < kC; ++c) {
      const double diagonal = gram[c * kC + c];
      if (diagonal <= 1e-12) {
        w[c] = 0.0;
        continue;
      }
      double gw = 0.0;
      for (std::size_t j = 0; j < kC; ++j) gw += gram[c * kC + j] * w[j];
      const double next = std::clamp(w[c] + (b[c] - gw) / diagonal, 0.0, 1.0);
      largest_step = std::max(largest_step, std::abs(next - w[c]));
      w[c] = next;
    }
    if (largest_step < 1e-6) break;
  }
  double wb = 0.0, wgw = 0.0;
  for (std::size_t i = 0; i < kC; ++i) {
    wb += w[i] * b[i];
    for (std::size_t j = 0; j < kC; ++j) wgw += w[i] * gram[i * kC + j] * w[j];
  }
  for (std::size_t c = 0; c < kC; ++c) weights[c] = static_cast<float>(w[c]);
  return std::max(0.0, dd - 2.0 * wb + wgw);
}

}  // namespace fw::physics
