#include "face_models.hpp"

#include <algorithm>

#include "face_model.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/avatar_tissue.hpp"

namespace fw::server {

FaceModels::FaceModels(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

std::shared_ptr<const FaceModel> FaceModels::find(const std::string& version) {
  std::lock_guard lock(mutex_);
  const auto it = models_.find(version);
  if (it == models_.end()) return nullptr;
  recent_.splice(recent_.begin(), recent_, it->second.place);
  return it->second.model;
}

std::shared_ptr<const FaceModel> FaceModels::build(const std::string& version, std::span<const std::uint8_t> bytes,
                                                   std::string& error) {
  if (auto found = find(version)) return found;
  if (before_build_) before_build_();
  model::AvatarPackage package;
  if (!model::parse_avatar_package(bytes, package, error)) return nullptr;
  // Outside the lock: two rooms asking for one new face at once may both
  // build it (the second kept replaces the first; both are the same face).
  auto built = std::make_shared<FaceModel>();
  built->avatar = model::make_avatar_model(model::generic_face(), package.fitted_vertices, package.head_outline);
  built->tissue = physics::build_avatar_tissue_model(built->avatar, physics::generic_tissue_model());
  built->correctives = std::make_shared<const physics::CorrectiveBasis>(
      physics::CorrectiveBasis::from_morphs(built->avatar.correctives, built->tissue->basis));
  keep(version, built);
  return built;
}

void FaceModels::keep(const std::string& version, std::shared_ptr<const FaceModel> model) {
  std::lock_guard lock(mutex_);
  ++builds_;
  if (const auto it = models_.find(version); it != models_.end()) {
    recent_.splice(recent_.begin(), recent_, it->second.place);
    it->second.model = std::move(model);
  } else {
    recent_.push_front(version);
    models_.emplace(version, Entry{std::move(model), recent_.begin()});
  }
  // Over the bound: the least recently asked for that no room holds go.
  for (auto it = recent_.end(); models_.size() > capacity_ && it != recent_.begin();) {
    --it;
    const auto entry = models_.find(*it);
    if (entry->second.model.use_count() > 1) continue;  // a room wears it
    models_.erase(entry);
    it = recent_.erase(it);
  }
}

std::size_t FaceModels::size() const {
  std::lock_guard lock(mutex_);
  return models_.size();
}

std::uint64_t FaceModels::builds() const {
  std::lock_guard lock(mutex_);
  return builds_;
}

}  // namespace fw::server
