#pragma once
// The projective-dynamics solver's factored system matrices of one tissue
// model, one per step length, made on first use and then shared by every
// face of that model (Bouaziz et al. 2014, sec. 4: the global matrix
// M/h^2 + sum w A^T A depends on the topology, the masses, the weights and
// the step, never on where the nodes are, so one factorisation serves every
// face and every frame).
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>

namespace fw::physics {

struct TissueModel;
namespace detail {
class ProjectiveSystem;
}

class ProjectiveSystemCache {
 public:
  ProjectiveSystemCache() = default;
  // A copied model may be changed before it is used (another material, other
  // weights): the copy starts with no systems rather than someone else's.
  ProjectiveSystemCache(const ProjectiveSystemCache&) {}
  ProjectiveSystemCache& operator=(const ProjectiveSystemCache&);

  /// The system of `model` for steps of `step_s` seconds; factors it on the
  /// first call (a few milliseconds). Thread-safe.
  std::shared_ptr<const detail::ProjectiveSystem> get(const TissueModel& model, float step_s) const;
  /// Systems held now, and their bytes.
  std::size_t size() const;
  std::size_t memory_bytes() const;

 private:
  mutable std::mutex mutex_;
  mutable std::map<float, std::shared_ptr<const detail::ProjectiveSystem>> systems_;
};

}  // namespace fw::physics
