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
// Solves a x = y in place (y becomes x) for a symmetric positive definite
// m x m matrix a (row-major, stride kC) by Cholesky; false when a pivot is
// not clearly positive (rows nearly dependent), leaving y undefined.
bool solve_positive_definite(std::array<double, kC * kC>& a, std::array<double, kC>& y, std::size_t m) {
  for (std::size_t j = 0; j < m; ++j) {
    double d = a[j * kC + j];
    for (std::size_t k = 0; k < j; ++k) d -= a[j * kC + k] * a[j * kC + k];
    if (!(d > 1e-12 * a[j * kC + j])) return false;
    d = std::sqrt(d);
    a[j * kC + j] = d;
    for (std::size_t i = j + 1; i < m; ++i) {
      double v = a[i * kC + j];
      for (std::size_t k = 0; k < j; ++k) v -= a[i * kC + k] * a[j * kC + k];
      a[i * kC + j] = v / d;
    }
  }
  for (std::size_t i = 0; i < m; ++i) {  // L z = y
    double v = y[i];
    for (std::size_t k = 0; k < i; ++k) v -= a[i * kC + k] * y[k];
    y[i] = v / a[i * kC + i];
  }
  for (std::size_t i = m; i-- > 0;) {  // L^T x = z
    double v = y[i];
    for (std::size_t k = i + 1; k < m; ++k) v -= a[k * kC + i] * y[k];
    y[i] = v / a[i * kC + i];
  }
  return true;
}

// Rounds of exact steps on the free weights (below) at most: each frees or
// binds at least one weight, and a face rarely has more than a few units
// on the move at once.
constexpr int kSubspaceRounds = 6;

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
  auto move = [&](std::size_t c, double step) {
    w[c] += step;
    const double* column = gram.data() + c * kC;
    for (std::size_t j = 0; j < kC; ++j) r[j] -= column[j] * step;
  };
  // Gauss-Seidel sweeps until no weight moves by 1e-6 or `limit` are done;
  // true if they settled.
  auto sweep_until = [&](int limit) {
    for (int sweep = 0; sweep < limit; ++sweep) {
      double largest_step = 0.0;  // warm-started, a few sweeps usually do
      for (std::size_t c = 0; c < kC; ++c) {
        const double diagonal = gram[c * kC + c];
        if (diagonal <= 1e-12) {  // an empty row: its column of G is 0 too
          w[c] = 0.0;
          continue;
        }
        const double step = std::clamp(w[c] + r[c] / diagonal, 0.0, 1.0) - w[c];
        if (step == 0.0) continue;
        largest_step = std::max(largest_step, std::abs(step));
        move(c, step);
      }
      if (largest_step < 1e-6) return true;
    }
    return false;
  };
  // Gauss-Seidel crawls along rows that are nearly parallel: the jaw's AU 26
  // and 27 differ mostly in how far they open it, and from rest 30 sweeps
  // took a settled AU 27 to 0.63, in steps too small to tell from settling.
  // So the weights strictly inside [0,1] then solve their own normal
  // equations exactly with the others held (the subspace step of active-set
  // methods), moving no further than keeps every one in the box, and sweeps
  // free or bind weights; done once a whole exact step leaves the sweeps
  // nothing to move. A face moves a few units at a time: the step is a
  // Cholesky solve of a few rows.
  sweep_until(sweeps);
  for (int round = 0; round < kSubspaceRounds; ++round) {
    std::array<std::size_t, kC> free{};
    std::size_t m = 0;
    for (std::size_t c = 0; c < kC; ++c)
      if (w[c] > 0.0 && w[c] < 1.0 && gram[c * kC + c] > 1e-12) free[m++] = c;
    if (m == 0) break;
    std::array<double, kC * kC> a{};
    std::array<double, kC> target{};
    for (std::size_t i = 0; i < m; ++i) {
      target[i] = r[free[i]];  // b_F - G_F* w + G_FF w_F: the held weights' part stays
      for (std::size_t j = 0; j < m; ++j) {
        const double g = gram[free[i] * kC + free[j]];
        a[i * kC + j] = g;
        target[i] += g * w[free[j]];
      }
    }
    if (!solve_positive_definite(a, target, m)) break;
    double reach = 1.0;  // how far toward the exact solution the box allows
    for (std::size_t i = 0; i < m; ++i) {
      const double from = w[free[i]], to = target[i];
      if (to < 0.0) reach = std::min(reach, from / (from - to));
      if (to > 1.0) reach = std::min(reach, (1.0 - from) / (to - from));
    }
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t c = free[i];
      move(c, std::clamp(w[c] + reach * (target[i] - w[c]), 0.0, 1.0) - w[c]);
    }
    if (sweep_until(sweeps) && reach == 1.0) break;
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
