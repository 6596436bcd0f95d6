#include "fw/physics/au_projection.hpp"

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

constexpr std::size_t kC = codec::kAuChannelCount;

// Random, nearly independent rows (like AUs that move different regions).
AuBasis random_basis(unsigned seed, std::size_t n) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::vector<float> rows(kC * n);
  for (float& x : rows) x = normal(rng) * 0.01f;
  return AuBasis::from_rows(rows, n);
}

std::vector<float> combine(const AuBasis& b, const std::array<float, kC>& w) {
  std::vector<float> d(b.length, 0.0f);
  for (std::size_t c = 0; c < kC; ++c)
    for (std::size_t k = 0; k < b.length; ++k) d[k] += w[c] * b.at(c, k);
  return d;
}

TEST(AuBasis, QuantisesToAFewMicrometres) {
  std::vector<float> rows(kC * 3, 0.0f);
  rows[0] = 0.1f;
  rows[1] = -0.0333f;
  rows[5] = 0.02f;
  const AuBasis b = AuBasis::from_rows(rows, 3);
  EXPECT_NEAR(b.at(0, 0), 0.1f, 1e-7f);
  EXPECT_NEAR(b.at(0, 1), -0.0333f, 0.1f / 32767.0f);
  EXPECT_NEAR(b.at(1, 2), 0.02f, 1e-7f);
  EXPECT_EQ(b.at(2, 0), 0.0f) << "an empty row stays empty";
  EXPECT_NEAR(b.gram[0], 0.1 * 0.1 + 0.0333 * 0.0333, 1e-6);
}

TEST(ProjectOntoBasis, RecoversWeightsInRange) {
  const unsigned seed = 4711;
  SCOPED_TRACE(seed);
  const AuBasis b = random_basis(seed, 600);
  std::mt19937 rng(seed + 1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::array<float, kC> truth{};
  for (float& w : truth) w = u(rng);
  std::array<float, kC> w{};
  const double residual = project_onto_basis(b, combine(b, truth), w, 200);
  for (std::size_t c = 0; c < kC; ++c) EXPECT_NEAR(w[c], truth[c], 1e-3f) << c;
  EXPECT_LT(residual, 1e-8);
}

TEST(ProjectOntoBasis, ClampsWeightsToTheirRange) {
  const AuBasis b = random_basis(99, 600);
  std::array<float, kC> truth{};
  truth[3] = 1.8f;
  truth[5] = -0.7f;
  std::array<float, kC> w{};
  const double residual = project_onto_basis(b, combine(b, truth), w, 200);
  EXPECT_NEAR(w[3], 1.0f, 1e-4f);
  EXPECT_NEAR(w[5], 0.0f, 1e-4f);
  EXPECT_GT(residual, 0.0) << "what the clamped weights cannot explain is residual";
}

// Two rows nearly parallel (the jaw's AU 26 and 27 differ mostly in how
// far they open it): Gauss-Seidel alone crawls along them, 30 sweeps from
// rest leaving the weights far off; the exact step on the free weights
// reaches them within the default sweeps, bounds included.
TEST(ProjectOntoBasis, NearlyParallelRowsConvergeWithinTheDefaultSweeps) {
  std::mt19937 rng(17);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  const std::size_t n = 600;
  std::vector<float> rows(kC * n);
  for (float& x : rows) x = normal(rng) * 0.01f;
  for (std::size_t k = 0; k < n; ++k) rows[1 * n + k] = 2.0f * rows[0 * n + k] + 0.02f * rows[1 * n + k];
  const AuBasis b = AuBasis::from_rows(rows, n);
  const double cosine = b.gram[1] / std::sqrt(b.gram[0] * b.gram[kC + 1]);
  ASSERT_GT(cosine, 0.999) << "the test needs nearly parallel rows";
  for (const auto& [first, second] : {std::pair{0.3f, 0.8f}, std::pair{0.0f, 1.0f}, std::pair{1.0f, 0.2f}}) {
    std::array<float, kC> truth{};
    truth[0] = first, truth[1] = second, truth[4] = 0.5f;
    std::array<float, kC> w{};
    const double residual = project_onto_basis(b, combine(b, truth), w);
    EXPECT_NEAR(w[0], first, 1e-3f);
    EXPECT_NEAR(w[1], second, 1e-3f);
    EXPECT_NEAR(w[4], 0.5f, 1e-3f);
    EXPECT_LT(residual, 1e-7);  // B d is summed in floats, and these rows magnify its rounding
  }
}

TEST(ProjectOntoBasis, ZeroDisplacementGivesZeroWeights) {
  const AuBasis b = random_basis(5, 100);
  std::array<float, kC> w{};
  w.fill(0.5f);  // a warm start far from the answer
  EXPECT_NEAR(project_onto_basis(b, std::vector<float>(b.length, 0.0f), w, 200), 0.0, 1e-12);
  for (float x : w) EXPECT_NEAR(x, 0.0f, 1e-4f);
}

}  // namespace
}  // namespace fw::physics
