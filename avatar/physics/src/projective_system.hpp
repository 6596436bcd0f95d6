#pragma once
// The global step of projective dynamics (Bouaziz, Martin, Liu, Kavan &
// Pauly 2014, "Projective Dynamics: Fusing Constraint Projections for Fast
// Simulation", SIGGRAPH, eq. 10-11) for one tissue model and one step
// length h: the constraints with their weights, and the matrix
//
//   S = M / h^2 + c M / h + (1 + beta / h) sum_i w_i A_i^T A_i
//
// over the moving nodes that are not held (the bone layer and the held
// outline are prescribed positions, moved to the right-hand side), with c
// each node's bond to its bone (TissueMaterial::bone_damping), factored
// once as P^T L D L^T P. The same matrix serves x, y and z and every face of
// the model, so a solve takes many right-hand sides at once: rows of up to
// 48 floats, the three coordinates of up to 16 faces side by side, so that
// every nonzero of L is a few vector operations across faces.
//
// The matrix depends on the topology, the masses, the weights and h, never
// on the rest shape: every avatar's fitted face shares the generic face's
// (ProjectiveFactor, through TissueModel::projective_reference) and keeps
// its own rest lengths and volumes in the local step, so faces of
// different avatars go in one batch.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "fw/physics/tissue_model.hpp"

namespace fw::physics::detail {

/// Faces whose right-hand sides one solve interleaves.
inline constexpr std::size_t kMaxBatchFaces = 16;

class ProjectiveSystem;

/// S = M / h^2 + c M / h + (1 + beta / h) sum w A^T A over the free nodes,
/// factored.
class ProjectiveFactor {
 public:
  /// Factors the matrix of `constraints` (their nodes and weights) over the
  /// free nodes of `model`.
  ProjectiveFactor(const TissueModel& model, const ProjectiveSystem& constraints, float step_s, float damping_s);

  /// Row (after the fill-reducing permutation) of node i, or -1 where the
  /// node is prescribed (bone, held outline).
  const std::vector<std::int32_t>& row_of_node() const { return row_of_node_; }
  const std::vector<std::uint16_t>& free_nodes() const { return free_nodes_; }
  /// The free nodes in node order: a loop over them walks the node arrays
  /// forward (by row, it jumps about them).
  const std::vector<std::uint16_t>& free_nodes_in_order() const { return free_in_order_; }
  std::size_t factor_nonzeros() const { return row_.size(); }
  std::size_t memory_bytes() const;
  void solve(float* y, std::size_t lanes) const;

 private:
  std::vector<std::int32_t> row_of_node_;
  std::vector<std::uint16_t> free_nodes_;  ///< by row
  std::vector<std::uint16_t> free_in_order_;
  // L, unit lower triangular, by columns (compressed sparse column), and D^-1.
  std::vector<std::uint32_t> column_start_;
  std::vector<std::uint16_t> row_;
  std::vector<float> value_, inverse_diagonal_;
};

class ProjectiveSystem {
 public:
  /// The constraints of `model` and their own factorisation.
  ProjectiveSystem(const TissueModel& model, float step_s);
  /// The constraints of `model` at its own rest shape with the weights and
  /// the factorisation of `reference`, a system of a model with the same
  /// topology and material (TissueModel::projective_reference).
  ProjectiveSystem(const TissueModel& model, const ProjectiveSystem& reference);

  float step_s() const { return step_s_; }
  /// Stiffness-proportional (Rayleigh) damping: the units resist their
  /// stretching speed by beta times their stiffness, seconds.
  float damping_s() const { return damping_s_; }
  /// The factored matrix, shared by every system made from the same reference:
  /// faces whose systems have the same factor share a solve.
  const ProjectiveFactor* factor() const { return factor_.get(); }

  // The constraints that move a free node. Springs: A = e_b - e_a, projected
  // onto their rest length. Volumes: A = the six nodes about their centroid,
  // projected onto the prism's rest volume.
  // A spring's weight is its stiffer slope k2 (past the knee); the local
  // step projects it to the length p at which k2 (L - p) is the biphasic
  // curve's force at its length L now, so the equilibrium is the curve's.
  std::vector<std::uint16_t> spring_a, spring_b;
  std::vector<float> spring_length, spring_knee_length, spring_weight;
  std::vector<float> spring_soft_share;  ///< k1 / k2
  std::vector<float> spring_compression;  ///< the curve's compression share (1: resists, 0: slack when short)
  std::array<std::vector<std::uint16_t>, 6> element_node;
  std::vector<float> element_rest_volume, element_weight;
  /// The bulk curve (bulk_curve.hpp): its knee and stiff ratio - 1. The
  /// weights hold the first slope; past the knee the projection reaches
  /// beyond the rest volume by the extra share, so the matrix stays the
  /// linear material's.
  float volume_knee = 0, volume_extra = 0;

  /// Row (after the fill-reducing permutation) of node i, or -1 where the
  /// node is prescribed (bone, held outline).
  const std::vector<std::int32_t>& row_of_node() const { return factor_->row_of_node(); }
  std::size_t free_count() const { return factor_->free_nodes().size(); }
  const std::vector<std::uint16_t>& free_nodes() const { return factor_->free_nodes(); }
  const std::vector<std::uint16_t>& free_nodes_in_order() const { return factor_->free_nodes_in_order(); }
  /// Nonzeros below the diagonal of L.
  std::size_t factor_nonzeros() const { return factor_->factor_nonzeros(); }
  /// Bytes of the constraints, and of the factor when this system owns it
  /// alone (a shared factor is counted where it was made).
  std::size_t memory_bytes() const;

  /// Solves S x = b in place for `lanes` right-hand sides interleaved row by
  /// row (y[row * lanes + lane], rows in permuted order); lanes is 3, 6, 12,
  /// 24 or 48.
  void solve(float* y, std::size_t lanes) const { factor_->solve(y, lanes); }

 private:
  void gather_constraints(const TissueModel& model);

  float step_s_ = 0, damping_s_ = 0;
  std::shared_ptr<const ProjectiveFactor> factor_;
  bool owns_factor_ = true;
};

/// Padded lanes for `faces` faces: 3 coordinates each, rounded up to a
/// width solve() takes.
std::size_t lanes_for(std::size_t faces);

}  // namespace fw::physics::detail
