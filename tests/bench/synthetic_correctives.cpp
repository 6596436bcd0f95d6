#include "synthetic_correctives.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "splitmix_random.hpp"

namespace fw::bench {
namespace {

using codec::kAuChannelCount;
using codec::kCorrectiveCount;

// Largest weight: the residual is a fraction of the AU motion (0.4 mm RMS
// against several mm), so its components stay well inside [-1, 1].
constexpr double kAmplitude = 0.5;
// Share of the AU channels each component draws on, and products per component.
constexpr double kMixShare = 0.3;
constexpr int kProducts = 3;
// The residual follows the muscles through the tissue's visco-elastic lag:
// an assumed time constant of the order of the face's damped spring nodes,
// enough to give the weights the bandwidth of the AU motion, not more.
constexpr double kLagSeconds = 0.06;

using Numbers = SplitMixRandom;

struct Product {
  std::size_t a, b;
  double weight;
};

struct Component {
  std::array<double, kAuChannelCount> mix{};
  std::array<Product, kProducts> products{};

  double target(const codec::FaceParams& face) const {
    double sum = 0;
    for (std::size_t c = 0; c < kAuChannelCount; ++c) sum += mix[c] * face.au[c];
    for (const Product& p : products) sum += p.weight * face.au[p.a] * face.au[p.b];
    return kAmplitude * std::tanh(sum);
  }
};

std::array<Component, kCorrectiveCount> make_components(std::uint64_t seed) {
  Numbers numbers(seed);
  std::array<Component, kCorrectiveCount> components{};
  for (Component& k : components) {
    for (double& m : k.mix) m = numbers.uniform(0, 1) < kMixShare ? numbers.uniform(-1.5, 1.5) : 0.0;
    for (Product& p : k.products)
      p = {numbers.index(kAuChannelCount), numbers.index(kAuChannelCount), numbers.uniform(-3.0, 3.0)};
  }
  return components;
}

}  // namespace

void add_synthetic_correctives(behavior::Scene& scene, std::uint64_t seed) {
  const std::array<Component, kCorrectiveCount> components = make_components(seed);
  const double follow = 1.0 - std::exp(-1.0 / (kLagSeconds * scene.fps));
  for (behavior::SceneAvatar& avatar : scene.avatars) {
    std::array<double, kCorrectiveCount> weight{};
    for (codec::FaceParams& face : avatar.ticks)
      for (std::size_t k = 0; k < kCorrectiveCount; ++k) {
        weight[k] += (components[k].target(face) - weight[k]) * follow;
        face.corrective[k] = static_cast<float>(weight[k]);
      }
  }
}

void clear_correctives(behavior::Scene& scene) {
  for (behavior::SceneAvatar& avatar : scene.avatars)
    for (codec::FaceParams& face : avatar.ticks) face.corrective = {};
}

bool has_correctives(const behavior::Scene& scene) {
  for (const behavior::SceneAvatar& avatar : scene.avatars)
    for (const codec::FaceParams& face : avatar.ticks)
      for (const float w : face.corrective)
        if (w != 0.0f) return true;
  return false;
}

}  // namespace fw::bench
