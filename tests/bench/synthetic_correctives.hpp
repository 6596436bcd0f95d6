#pragma once
// Corrective weights for scenes recorded before the physics face set them
// (the codec benchmark's cost of the corrective channels, the golden
// vectors): made from each avatar's own action units, so they move when
// and about as fast as its face does. The integrator re-measures with the
// real ones once the room simulation records them.
#include <cstdint>

#include "fw/behavior/scene_file.hpp"

namespace fw::bench {

/// Sets every face's corrective weights from its action units: per
/// component, a fixed random mix of the AU intensities and of a few
/// products of two (the residual the components stand for is the tissue's
/// non-linear response to combined units), squashed into +-0.5 and lagged
/// by the tissue's response time. Deterministic for a seed.
void add_synthetic_correctives(behavior::Scene& scene, std::uint64_t seed);

/// Sets every corrective weight of the scene to 0.
void clear_correctives(behavior::Scene& scene);

/// Whether some face of the scene carries a corrective weight.
bool has_correctives(const behavior::Scene& scene);

}  // namespace fw::bench
