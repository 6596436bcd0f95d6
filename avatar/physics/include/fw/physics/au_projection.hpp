#pragma once
// Kernel: the measurement step of the server pipeline. The simulated surface's
// displacement d is projected onto the AU basis B (one row per AU channel):
//   min_w |d - B^T w|^2  subject to 0 <= w <= 1,
// solved by projected Gauss-Seidel on the normal equations (B B^T) w = B d,
// which converges because B B^T is symmetric positive semi-definite.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::physics {

/// The AU basis, its rows quantised to 16 bits (one scale per row: a step
/// is the row's largest value / 32767, a few micrometres), which halves the
/// largest array a face's model holds.
struct AuBasis {
  std::size_t length = 0;                             ///< floats per row (3 #V)
  std::vector<std::int16_t> rows;                     ///< kAuChannelCount x length
  std::array<float, codec::kAuChannelCount> scale{};  ///< model units per step, per row
  std::vector<double> gram;                           ///< kAuChannelCount^2, B B^T of the quantised rows

  /// @param[in] rows    kAuChannelCount x length floats, model units
  /// @param[in] length  floats per row
  static AuBasis from_rows(std::span<const float> rows, std::size_t length);
  float at(std::size_t row, std::size_t k) const { return scale[row] * rows[row * length + k]; }
  std::size_t memory_bytes() const { return rows.capacity() * sizeof(std::int16_t) + gram.capacity() * sizeof(double); }
};

/// @param[in]     basis         the basis, basis.length == #displacement
/// @param[in]     displacement  #d floats (3 per vertex)
/// @param[in,out] weights       start values in, the solution out, each in [0,1]
/// @param[in]     sweeps        at most this many Gauss-Seidel passes, > 0 (fewer once no weight moves by 1e-6)
/// @return |d - B^T w|^2, the squared residual
double project_onto_basis(const AuBasis& basis, std::span<const float> displacement,
                          std::array<float, codec::kAuChannelCount>& weights, int sweeps = 30);

}  // namespace fw::physics
