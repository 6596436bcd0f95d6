// The face lab's skin age and looseness as a material between normal() and
// loose(), the behavioral-animation paper's two curves (Fig. 2a, 2b).
#include <algorithm>

#include "fw/physics/tissue_model.hpp"

namespace fw::physics {

TissueMaterial TissueMaterial::aged(float age, float looseness) {
  const TissueMaterial young = normal(), old = loose();
  const float a = std::clamp(age, 0.0f, 1.0f), l = std::clamp(looseness, 0.0f, 1.0f);
  TissueMaterial m = young;
  // Only the skin layers' curves differ between the two; the muscle layer,
  // damping, volume and mass stay normal()'s, as loose() keeps them.
  for (std::size_t k = 0; k < kSpringKindCount; ++k) {
    StressStrainCurve& c = m.curves[k];
    c.stiffness = young.curves[k].stiffness + a * (old.curves[k].stiffness - young.curves[k].stiffness);
    c.residual_strain =
        young.curves[k].residual_strain + l * (old.curves[k].residual_strain - young.curves[k].residual_strain);
    // Looser skin is also slacker: it loses its resistance to compression
    // as it gains length, so a slider moves the material without a jump.
    c.compression_share = young.curves[k].compression_share +
                          l * (old.curves[k].compression_share - young.curves[k].compression_share);
  }
  return m;
}

}  // namespace fw::physics
