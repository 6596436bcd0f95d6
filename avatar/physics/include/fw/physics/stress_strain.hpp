#pragma once
// Kernel: the nonlinear stress-strain curve of one viscoelastic unit (a
// spring and a damper in parallel). Lee, Terzopoulos & Waters, "Realistic
// modeling for facial animation" (SIGGRAPH 1995), sec. 4: skin is biphasic,
// compliant at low strain (elastin) and several times stiffer once the
// collagen fibres straighten. The behavioral-animation paper (Fig. 2) makes
// the curve adjustable: a negative residual strain gives looser, aged skin.
#include <algorithm>

namespace fw::physics {

/// Piecewise-linear stress-strain curve, in force per unit strain of a unit
/// whose rest length is 1 (the simulation multiplies by the rest length, so
/// a spring's stiffness does not depend on how finely the mesh is cut).
struct StressStrainCurve {
  float stiffness = 1.0f;         ///< k1: slope below the knee, > 0
  float stiff_ratio = 3.0f;       ///< k2 / k1 above the knee, >= 1
  float knee_strain = 0.15f;      ///< strain where the collagen takes over, > 0
  /// The strain the neutral mesh puts on the unit, relative to the unit's
  /// natural length: 0 = the neutral length is natural; negative = the unit
  /// is naturally longer, so it is slack until stretched by -residual_strain
  /// (the paper's looser, aged skin).
  float residual_strain = 0.0f;
  /// How much of k1 resists compression below the natural length: 1 for
  /// young skin; 0 for aged skin, whose slack fibres carry tension only
  /// (an elastic unit naturally longer than the neutral face hangs slack at
  /// rest instead of pushing its ends apart: Lee, Terzopoulos & Waters 1995
  /// model skin as fibres that straighten under tension; the
  /// behavioral-animation paper's Fig. 2b curve starts flat at rest).
  float compression_share = 1.0f;
};

/// Stress of the curve at `strain` (dimensionless, from the neutral length):
///   s(e) = k1 (max(0, e + r) + c min(0, e + r)) + (k2 - k1) max(0, e + r - knee)
/// with c the compression share.
/// @param[in] curve   the curve
/// @param[in] strain  (length - rest) / rest
/// @return force per unit rest length; positive pulls the ends together
inline float stress(const StressStrainCurve& curve, float strain) {
  const float e = strain + curve.residual_strain;
  const float linear = std::max(0.0f, e) + curve.compression_share * std::min(0.0f, e);
  return curve.stiffness * (linear + (curve.stiff_ratio - 1.0f) * std::max(0.0f, e - curve.knee_strain));
}

}  // namespace fw::physics
