#include "redefined_faces.hpp"

#include "fw/model/unit_morphs.hpp"

namespace fw::client {

RedefinedFaces::Face RedefinedFaces::package_arrived(std::uint32_t avatar, Face shipped, std::string& error) {
  Avatar& known = avatars_[avatar];
  known.shipped = std::move(shipped);
  return drawn(known, error);
}

RedefinedFaces::Face RedefinedFaces::units_arrived(const codec::UnitMorphs& units, std::string& error) {
  Avatar& known = avatars_[units.avatar];
  known.units = units;
  if (!known.shipped) return nullptr;
  return drawn(known, error);
}

void RedefinedFaces::forget(std::uint32_t avatar) { avatars_.erase(avatar); }

RedefinedFaces::Face RedefinedFaces::drawn(const Avatar& known, std::string& error) const {
  if (!known.units || known.units->units.empty()) return known.shipped;  // the shipped units
  const model::GenericFace& generic = model::generic_face();
  const auto set = model::unit_morph_set(*known.units, generic.skin.positions.size(), error);
  if (!set) return known.shipped;
  // A copy: the shipped face stays as it is, for a later restore.
  auto face = std::make_shared<render::AvatarAppearance>(*known.shipped);
  model::set_unit_morphs(face->avatar, generic, *set);
  return face;
}

}  // namespace fw::client
