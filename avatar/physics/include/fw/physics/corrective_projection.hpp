#pragma once
// Kernel: the corrective part of the measurement. What the AU basis B leaves
// of the skin's displacement d, r = d - B^T w, is projected onto the face's
// corrective components C (K rows, K <= codec::kCorrectiveCount; the
// principal components of that residual over a corpus of behaviour):
//   min_c |r - C^T c|^2  =>  c = (C C^T)^-1 C r, each then clamped to [-1,1].
// Since C r = C d - (C B^T) w, the residual is never formed: K dot products
// with d and a K x 29 product, a few microseconds.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/morph.hpp"
#include "fw/physics/au_projection.hpp"

namespace fw::physics {

struct CorrectiveBasis {
  std::size_t count = 0;              ///< components, <= kCorrectiveCount
  std::size_t length = 0;             ///< floats per row (3 #V)
  std::vector<float> rows;            ///< count x length, model units at weight 1
  std::vector<double> inverse_gram;   ///< count^2, (C C^T)^-1
  std::vector<double> cross;          ///< count x kAuChannelCount, C B^T with B as `au` holds it

  /// @param[in] components  at most kCorrectiveCount morphs, #V vertex deltas each (more are ignored)
  /// @param[in] au          the AU basis the face is measured against (length 3 #V)
  static CorrectiveBasis from_morphs(std::span<const model::Morph> components, const AuBasis& au);
  std::size_t memory_bytes() const {
    return rows.capacity() * sizeof(float) + (inverse_gram.capacity() + cross.capacity()) * sizeof(double);
  }
};

/// @param[in] basis         the components, basis.length == #displacement
/// @param[in] displacement  #d floats (3 per vertex), the skin's displacement from rest
/// @param[in] au_weights    the AU weights measured for the same displacement
/// @return the corrective weights, each in [-1,1]; 0 past basis.count
std::array<float, codec::kCorrectiveCount> project_corrective(
    const CorrectiveBasis& basis, std::span<const float> displacement,
    const std::array<float, codec::kAuChannelCount>& au_weights);

}  // namespace fw::physics
