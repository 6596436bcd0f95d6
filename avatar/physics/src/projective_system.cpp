#include "projective_system.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "hot_clones.hpp"
#include "wedge_volume.hpp"

namespace fw::physics::detail {
namespace {

// Stiffness-proportional (Rayleigh) damping, D = beta K (Baraff & Witkin
// 1998, "Large Steps in Cloth Simulation", likewise damp each condition
// along its own stiffness): the units resist their stretching speed, not
// the world, as the mass-spring solver's dampers do (their c / k is 0.7 to
// 3.3 ms in the skin and muscle layers, 10 in the fat). The slow modes
// near 5 Hz are damped by each node's bond to its bone, the material's
// bone_damping, as in the other solvers, and by implicit Euler itself.
// K here is the weights' L, which resists a unit's turning as much as its
// stretching, so beta damps more than the mass-spring dampers do. Over the
// held-out corpus, against the mass-spring face (two 17 ms steps a frame,
// ProjectiveStepper::kLongestStepS): beta 2 ms is 0.089 mm RMS from it and
// the corrective basis cuts the residual to 0.453; 0 comes nearer (0.076)
// but the basis then cuts only to 0.522 (a less damped face leaves more of
// its ringing outside a few components); 5 ms is 0.140 away. (At one 33 ms
// step a frame 5 ms was 0.172 away: README, "The projective solver".)
constexpr float kDampingS = 0.002f;

// Each width is built for AVX2 and for any x86-64 (hot_clones.hpp), without
// fused multiply-adds (CMakeLists.txt), so every width gives a lane the
// same bits: a face steps alike alone and in a batch.
template <std::size_t W>
inline __attribute__((always_inline)) void substitute(const std::uint32_t* start, const std::uint16_t* row,
                                                      const float* value, const float* inverse_diagonal, std::size_t n,
                                                      float* __restrict y) {
  // L z = b, column by column: z_j is final once its column is reached.
  for (std::size_t j = 0; j < n; ++j) {
    const float* __restrict zj = y + j * W;
    for (std::uint32_t p = start[j]; p < start[j + 1]; ++p) {
      float* __restrict zi = y + std::size_t(row[p]) * W;
      const float l = value[p];
      for (std::size_t k = 0; k < W; ++k) zi[k] -= l * zj[k];
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    const float d = inverse_diagonal[j];
    for (std::size_t k = 0; k < W; ++k) y[j * W + k] *= d;
  }
  // L^T x = z, last row first: row j of L^T is column j of L. Written as
  // the forward pass is, straight into the row (the rows below it, which it
  // reads, are distinct): summed in a local array, GCC left this pass
  // scalar, three quarters of the solve.
  for (std::size_t j = n; j-- > 0;) {
    float* __restrict xj = y + j * W;
    for (std::uint32_t p = start[j]; p < start[j + 1]; ++p) {
      const float* __restrict xi = y + std::size_t(row[p]) * W;
      const float l = value[p];
      for (std::size_t k = 0; k < W; ++k) xj[k] -= l * xi[k];
    }
  }
}

#define FW_SUBSTITUTE(W)                                                                                           \
  FW_HOT_CLONES void substitute_##W(const std::uint32_t* start, const std::uint16_t* row, const float* value, \
                                      const float* inverse_diagonal, std::size_t n, float* y) {                  \
    substitute<W>(start, row, value, inverse_diagonal, n, y);                                                    \
  }
FW_SUBSTITUTE(3)
FW_SUBSTITUTE(6)
FW_SUBSTITUTE(12)
FW_SUBSTITUTE(24)
FW_SUBSTITUTE(48)
#undef FW_SUBSTITUTE

}  // namespace

std::size_t lanes_for(std::size_t faces) {
  assert(faces >= 1 && faces <= kMaxBatchFaces);
  if (faces <= 1) return 3;
  if (faces <= 2) return 6;
  if (faces <= 4) return 12;
  if (faces <= 8) return 24;
  return 48;
}

namespace {

bool is_free(const TissueModel& m, std::size_t node) { return node < m.moving_node_count && m.inverse_mass[node] != 0.0f; }

}  // namespace

ProjectiveSystem::ProjectiveSystem(const TissueModel& m, float step_s) : step_s_(step_s), damping_s_(kDampingS) {
  gather_constraints(m);
  factor_ = std::make_shared<const ProjectiveFactor>(m, *this, step_s_, damping_s_);
}

ProjectiveSystem::ProjectiveSystem(const TissueModel& m, const ProjectiveSystem& reference)
    : step_s_(reference.step_s_), damping_s_(reference.damping_s_), factor_(reference.factor_), owns_factor_(false) {
  gather_constraints(m);
  // The same topology and material (TissueModel::projective_reference):
  // the same constraints in the same order, the springs' weights and curves
  // the same (a batch's local step takes them from its first face).
  if (spring_a != reference.spring_a || spring_b != reference.spring_b || element_node != reference.element_node ||
      spring_weight != reference.spring_weight || spring_soft_share != reference.spring_soft_share ||
      spring_compression != reference.spring_compression)
    throw std::invalid_argument("projective dynamics: a model shares the factorisation of one with another topology or material");
  // The prisms' weights are the reference's: they are what the factor holds.
  // Each face keeps its own rest volumes, so its rest shape is still the
  // exact equilibrium; away from rest its volume stiffness is the
  // reference's per prism (README, "Every avatar its own face").
  element_weight = reference.element_weight;
}

void ProjectiveSystem::gather_constraints(const TissueModel& m) {
  if (m.inverse_mass.size() < m.moving_node_count)
    throw std::invalid_argument("projective dynamics: the model has no masses");
  // Springs: the viscoelastic units' biphasic curves (stress_strain.hpp).
  // PD's weights are constants; the stiffer slope is the weight and the
  // projection bends the target length (projective_local_step.cpp), the
  // way quasi-Newton PD treats nonlinear materials (Liu, Bouaziz & Kavan
  // 2017, "Quasi-Newton Methods for Real-Time Simulation of Hyperelastic
  // Materials", ACM TOG 36(3)): exact at rest, slower to converge on the
  // soft branch.
  for (std::size_t s = 0; s < m.spring_count(); ++s) {
    if (!is_free(m, m.spring_a[s]) && !is_free(m, m.spring_b[s])) continue;
    const StressStrainCurve& c = m.material.curves[static_cast<std::size_t>(m.spring_kind[s])];
    spring_a.push_back(m.spring_a[s]);
    spring_b.push_back(m.spring_b[s]);
    const float stiff_ratio = std::max(c.stiff_ratio, 1.0f);
    spring_length.push_back(m.spring_rest[s] * (1.0f - c.residual_strain));
    spring_knee_length.push_back(m.spring_rest[s] * (1.0f - c.residual_strain + c.knee_strain));
    spring_weight.push_back(c.stiffness * stiff_ratio);
    spring_soft_share.push_back(1.0f / stiff_ratio);
    spring_compression.push_back(c.compression_share);
  }
  // The stiffer branch goes into the target, not the weight: weights at
  // the stiff slope (as the springs', above) kept most units moving after
  // 10 s, one iteration per step converging that much slower on the first
  // slope; a target past the rest volume settles as fast as before and
  // holds under the jaw at this ratio (x10 diverges; README).
  volume_knee = m.material.volume_knee;
  volume_extra = std::max(m.material.volume_stiff_ratio, 1.0f) - 1.0f;
  // Volumes: weight w = kappa s |grad V|^2 at rest, so that near rest the
  // projection's pull w lambda grad V, lambda = (V0 - V) / |grad V|^2, is the
  // mass-spring solver's kappa s (V0 - V) grad V (Lee et al. 1995, eq. 6).
  for (std::size_t e = 0; e < m.element_count(); ++e) {
    const auto nodes = m.element(e);
    if (std::none_of(nodes.begin(), nodes.end(), [&](std::uint16_t i) { return is_free(m, i); })) continue;
    float px[6], py[6], pz[6], gradient[6][3];
    for (std::size_t k = 0; k < 6; ++k) px[k] = m.rest_x[nodes[k]], py[k] = m.rest_y[nodes[k]], pz[k] = m.rest_z[nodes[k]];
    wedge_volume_gradient(px, py, pz, gradient);
    float g2 = 0.0f;
    for (const auto& g : gradient) g2 += g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    for (std::size_t k = 0; k < 6; ++k) element_node[k].push_back(nodes[k]);
    element_rest_volume.push_back(m.element_rest_volume[e]);
    element_weight.push_back(m.material.volume_stiffness * m.element_force_scale[e] * g2);
  }
}

ProjectiveFactor::ProjectiveFactor(const TissueModel& m, const ProjectiveSystem& c, float step_s, float damping_s) {
  std::vector<std::int32_t> index(m.node_count, -1);  // free index in node order
  std::vector<std::uint16_t> free_by_index;
  for (std::size_t i = 0; i < m.moving_node_count; ++i)
    if (is_free(m, i)) {
      index[i] = static_cast<std::int32_t>(free_by_index.size());
      free_by_index.push_back(static_cast<std::uint16_t>(i));
    }
  const std::size_t n = free_by_index.size();
  free_in_order_ = free_by_index;
  if (n == 0 || n > 65535) throw std::invalid_argument("projective dynamics: the model needs 1..65535 free nodes");

  // S over the free nodes, in node order.
  const double h = step_s, scale = 1.0 + double(damping_s) / h;
  // M / h^2, and the bond to the bone c M / h (implicit: ProjectiveStepper).
  const double mass = m.material.node_mass, bond = double(m.material.bone_damping) * mass / h;
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < n; ++i) entries.emplace_back(int(i), int(i), mass / (h * h) + bond);
  for (std::size_t s = 0; s < c.spring_a.size(); ++s) {
    const int a = index[c.spring_a[s]], b = index[c.spring_b[s]];
    const double w = scale * c.spring_weight[s];
    if (a >= 0) entries.emplace_back(a, a, w);
    if (b >= 0) entries.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) entries.emplace_back(a, b, -w), entries.emplace_back(b, a, -w);
  }
  for (std::size_t e = 0; e < c.element_weight.size(); ++e) {
    const double w = scale * c.element_weight[e];
    for (std::size_t k = 0; k < 6; ++k)
      for (std::size_t l = 0; l < 6; ++l) {
        const int a = index[c.element_node[k][e]], b = index[c.element_node[l][e]];
        if (a >= 0 && b >= 0) entries.emplace_back(a, b, w * ((k == l ? 1.0 : 0.0) - 1.0 / 6.0));
      }
  }
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(matrix);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("projective dynamics: the system is not positive definite");

  // Eigen solves with P b, L, D, L^T, P^-1: free node i sits in row P(i).
  const auto& permutation = ldlt.permutationP().indices();
  row_of_node_.assign(m.node_count, -1);
  free_nodes_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    row_of_node_[free_by_index[i]] = permutation(int(i));
    free_nodes_[std::size_t(permutation(int(i)))] = free_by_index[i];
  }
  const Eigen::SparseMatrix<double>& lower = ldlt.matrixL().nestedExpression();
  column_start_.assign(n + 1, 0);
  for (int j = 0; j < int(n); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.row() <= j) continue;  // the unit diagonal, where it is stored
      row_.push_back(static_cast<std::uint16_t>(it.row()));
      value_.push_back(static_cast<float>(it.value()));
    }
    column_start_[std::size_t(j) + 1] = static_cast<std::uint32_t>(row_.size());
  }
  inverse_diagonal_.resize(n);
  for (std::size_t i = 0; i < n; ++i) inverse_diagonal_[i] = static_cast<float>(1.0 / ldlt.vectorD()(int(i)));
}

std::size_t ProjectiveFactor::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return sizeof(*this) + bytes(row_of_node_) + bytes(free_nodes_) + bytes(free_in_order_) + bytes(column_start_) + bytes(row_) + bytes(value_) +
         bytes(inverse_diagonal_);
}

std::size_t ProjectiveSystem::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t total = sizeof(*this) + bytes(spring_a) + bytes(spring_b) + bytes(spring_length) + bytes(spring_knee_length) + bytes(spring_weight) + bytes(spring_soft_share) + bytes(spring_compression) +
                      bytes(element_rest_volume) + bytes(element_weight);
  for (const auto& corner : element_node) total += bytes(corner);
  return total + (owns_factor_ ? factor_->memory_bytes() : 0);
}

void ProjectiveFactor::solve(float* y, std::size_t lanes) const {
  const std::size_t n = free_nodes_.size();
  const auto* start = column_start_.data();
  const auto* row = row_.data();
  const float* value = value_.data();
  const float* diagonal = inverse_diagonal_.data();
  switch (lanes) {
    case 3: return substitute_3(start, row, value, diagonal, n, y);
    case 6: return substitute_6(start, row, value, diagonal, n, y);
    case 12: return substitute_12(start, row, value, diagonal, n, y);
    case 24: return substitute_24(start, row, value, diagonal, n, y);
    case 48: return substitute_48(start, row, value, diagonal, n, y);
    default: throw std::invalid_argument("projective dynamics: a solve takes 3, 6, 12, 24 or 48 lanes");
  }
}

}  // namespace fw::physics::detail

namespace fw::physics {

ProjectiveSystemCache& ProjectiveSystemCache::operator=(const ProjectiveSystemCache&) {
  std::lock_guard lock(mutex_);
  systems_.clear();
  return *this;
}

std::shared_ptr<const detail::ProjectiveSystem> ProjectiveSystemCache::get(const TissueModel& model, float step_s) const {
  // Frames come at a handful of rates (and their lengths on a 2 % grid,
  // ProjectiveStepper::tissue_step); a model fed from everywhere starts over.
  constexpr std::size_t kMaxSystems = 8;
  std::lock_guard lock(mutex_);
  auto it = systems_.find(step_s);
  if (it != systems_.end()) return it->second;
  if (systems_.size() >= kMaxSystems) systems_.clear();
  // A model that shares its reference's factorisation (an avatar's fitted
  // face, TissueModel::projective_reference) takes the reference's system
  // for this step, made first if need be, with its own rest shape.
  auto system = model.projective_reference
                    ? std::make_shared<const detail::ProjectiveSystem>(
                          model, *model.projective_reference->projective_systems.get(*model.projective_reference, step_s))
                    : std::make_shared<const detail::ProjectiveSystem>(model, step_s);
  systems_.emplace(step_s, system);
  return system;
}

std::size_t ProjectiveSystemCache::size() const {
  std::lock_guard lock(mutex_);
  return systems_.size();
}

std::size_t ProjectiveSystemCache::memory_bytes() const {
  std::lock_guard lock(mutex_);
  std::size_t bytes = 0;
  for (const auto& [step, system] : systems_) bytes += system->memory_bytes();
  return bytes;
}

}  // namespace fw::physics
