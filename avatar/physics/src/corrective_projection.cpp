#include "fw/physics/corrective_projection.hpp"

#include <algorithm>
#include <cassert>

#include <Eigen/Dense>

namespace fw::physics {

namespace {
constexpr std::size_t kAuRows = codec::kAuChannelCount;
}  // namespace

CorrectiveBasis CorrectiveBasis::from_morphs(std::span<const model::Morph> components, const AuBasis& au) {
  CorrectiveBasis b;
  b.count = std::min(components.size(), codec::kCorrectiveCount);
  b.length = au.length;
  b.rows.assign(b.count * b.length, 0.0f);
  for (std::size_t k = 0; k < b.count; ++k) {
    const auto& delta = components[k].vertex_delta;
    assert(3 * delta.size() == b.length);
    for (std::size_t v = 0; v < delta.size(); ++v)
      for (int a = 0; a < 3; ++a) b.rows[k * b.length + 3 * v + a] = delta[v][a];
  }
  if (b.count == 0) return b;  // no components: every weight stays 0
  Eigen::MatrixXd gram(b.count, b.count);
  for (std::size_t i = 0; i < b.count; ++i)
    for (std::size_t j = 0; j < b.count; ++j) {
      double sum = 0.0;
      for (std::size_t n = 0; n < b.length; ++n) sum += double(b.rows[i * b.length + n]) * b.rows[j * b.length + n];
      gram(Eigen::Index(i), Eigen::Index(j)) = sum;
    }
  // Components the fit made orthogonal stay nearly so once cloned onto a
  // fitted face; the pseudo-inverse guards a degenerate one all the same.
  const Eigen::MatrixXd inverse = gram.completeOrthogonalDecomposition().pseudoInverse();
  b.inverse_gram.resize(b.count * b.count);
  for (std::size_t i = 0; i < b.count; ++i)
    for (std::size_t j = 0; j < b.count; ++j) b.inverse_gram[i * b.count + j] = inverse(Eigen::Index(i), Eigen::Index(j));
  b.cross.assign(b.count * kAuRows, 0.0);
  for (std::size_t k = 0; k < b.count; ++k)
    for (std::size_t c = 0; c < kAuRows; ++c) {
      double sum = 0.0;
      for (std::size_t n = 0; n < b.length; ++n) sum += double(b.rows[k * b.length + n]) * au.at(c, n);
      b.cross[k * kAuRows + c] = sum;
    }
  return b;
}

std::array<float, codec::kCorrectiveCount> project_corrective(const CorrectiveBasis& basis,
                                                              std::span<const float> displacement,
                                                              const std::array<float, kAuRows>& au_weights) {
  std::array<float, codec::kCorrectiveCount> out{};
  const std::size_t n = displacement.size();
  assert(basis.count == 0 || basis.length == n);
  std::array<double, codec::kCorrectiveCount> cr{};
  for (std::size_t k = 0; k < basis.count; ++k) {
    const float* row = basis.rows.data() + k * n;
    // Eight lanes summed apart, as in au_projection.cpp, so that it vectorises.
    float lanes[8] = {};
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
      for (std::size_t j = 0; j < 8; ++j) lanes[j] += row[i + j] * displacement[i + j];
    float sum = 0.0f;
    for (; i < n; ++i) sum += row[i] * displacement[i];
    for (float lane : lanes) sum += lane;
    double au = 0.0;
    for (std::size_t c = 0; c < kAuRows; ++c) au += basis.cross[k * kAuRows + c] * au_weights[c];
    cr[k] = double(sum) - au;
  }
  for (std::size_t k = 0; k < basis.count; ++k) {
    double w = 0.0;
    for (std::size_t j = 0; j < basis.count; ++j) w += basis.inverse_gram[k * basis.count + j] * cr[j];
    out[k] = static_cast<float>(std::clamp(w, -1.0, 1.0));
  }
  return out;
}

}  // namespace fw::physics
