#include "fw/physics/au_projection.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "hot_clones.hpp"

namespace fw::physics {

namespace {
constexpr std::size_t kC = codec::kAuChannelCount;

// out += scale G w, column by column so that the inner loop runs across
// rows (independent sums that vectorise) rather than along one.
void add_gram_times(const std::vector<double>& gram, const std::array<double, kC>& w, double scale, std::array<double, kC>& out) {
  for (std::size_t j = 0; j < kC; ++j) {
    const double wj = scale * w[j];
    if (wj == 0.0) continue;
    const double* column = gram.data() + j * kC;
    for (std::size_t i = 0; i < kC; ++i) out[i] += column[i] * wj;
  }
}
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

FW_HOT_CLONES
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
  // d.d likewise in lanes summed apart (one sum would be a chain of 684
  // dependent additions).
  double dd_lanes[8] = {};
  std::size_t k = 0;
  for (; k + 8 <= n; k += 8)
    for (std::size_t j = 0; j < 8; ++j) dd_lanes[j] += double(displacement[k + j]) * displacement[k + j];
  double dd = 0.0;
  for (; k < n; ++k) dd += double(displacement[k]) * displacement[k];
  for (double lane : dd_lanes) dd += lane;
  const std::vector<double>& gram = basis.gram;
  std::array<double, kC> w{};
  for (std::size_t c = 0; c < kC; ++c) w[c] = std::clamp(double(weights[c]), 0.0, 1.0);
  // The gradient r = b - G w is kept up to date as the weights move (G is
  // symmetric: a weight's column is its row), so a coordinate step costs
  // one short vector update instead of a 29-term dot product whose sum is
  // a chain of dependent additions; the sweeps take the same steps.
  std::array<double, kC> r = b;
  add_gram_times(gram, w, -1.0, r);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    double largest_step = 0.0;  // warm-started, a few sweeps usually do
    for (std::size_t c = 0; c < kC; ++c) {
      const double diagonal = gram[c * kC + c];
      if (diagonal <= 1e-12) {  // an empty row: its column of G is 0 too
        w[c] = 0.0;
        continue;
      }
      const double next = std::clamp(w[c] + r[c] / diagonal, 0.0, 1.0), step = next - w[c];
      if (step == 0.0) continue;
      largest_step = std::max(largest_step, std::abs(step));
      w[c] = next;
      const double* column = gram.data() + c * kC;
      for (std::size_t j = 0; j < kC; ++j) r[j] -= column[j] * step;
    }
    if (largest_step < 1e-6) break;
  }
  // |d - B^T w|^2 = d.d - 2 w.b + w.G w, with G w formed afresh (not from r,
  // which carries the sweeps' rounding).
  std::array<double, kC> gw{};
  add_gram_times(gram, w, 1.0, gw);
  double wb = 0.0, wgw = 0.0;
  for (std::size_t i = 0; i < kC; ++i) wb += w[i] * b[i], wgw += w[i] * gw[i];
  for (std::size_t c = 0; c < kC; ++c) weights[c] = static_cast<float>(w[c]);
  return std::max(0.0, dd - 2.0 * wb + wgw);
}

}  // namespace fw::physics
