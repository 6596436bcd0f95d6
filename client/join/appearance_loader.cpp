#include "appearance_loader.hpp"

#include "fw/model/avatar_package.hpp"
#include "fw/render/avatar_appearance.hpp"

namespace fw::client {

AppearanceLoader::Changes AppearanceLoader::take_new(RoomState& state) {
  Changes changes;
  std::lock_guard lock(state.mutex);
  for (const auto& [id, avatar] : state.avatars) {
    if (!avatar.package) continue;
    auto& serial = loaded_[id];
    if (serial == avatar.package_serial) continue;
    serial = avatar.package_serial;
    changes.packages.emplace_back(id, avatar.package);
  }
  for (const auto& [id, units] : state.unit_morphs) {
    const auto shown = units_loaded_.find(id);
    if (shown != units_loaded_.end() && shown->second == units.version) continue;
    units_loaded_[id] = units.version;
    changes.units.push_back(units);
  }
  // Those who left (the state forgets both their package and their units):
  // their faces are let go.
  const auto left = [&state](std::uint32_t id) { return !state.avatars.contains(id) && !state.unit_morphs.contains(id); };
  for (const auto& [id, serial] : loaded_)
    if (left(id)) changes.gone.push_back(id);
  for (const auto& [id, version] : units_loaded_)
    if (left(id) && !loaded_.contains(id)) changes.gone.push_back(id);
  for (const std::uint32_t id : changes.gone) {
    loaded_.erase(id);
    units_loaded_.erase(id);
  }
  return changes;
}

void AppearanceLoader::load_new(RoomState& state, RoomView& view) {
  Changes changes = take_new(state);
  for (const std::uint32_t id : changes.gone) faces_.forget(id);
  for (const auto& [id, bytes] : changes.packages) {
    model::AvatarPackage package;
    auto appearance = std::make_shared<render::AvatarAppearance>();
    std::string error;
    if (!model::parse_avatar_package(*bytes, package, error) ||
        !render::load_avatar_appearance(package, *appearance, error)) {
      log_ << "avatar " << id << ": its package cannot be shown (" << error << "); drawing the generic face\n";
      continue;
    }
    auto face = faces_.package_arrived(id, std::move(appearance), error);
    if (!error.empty()) log_ << "avatar " << id << ": " << error << "; drawing its shipped units\n";
    view.set_appearance(id, std::move(face));
  }
  for (const codec::UnitMorphs& units : changes.units) {
    std::string error;
    auto face = faces_.units_arrived(units, error);
    if (!error.empty()) log_ << "avatar " << units.avatar << ": " << error << "; drawing its shipped units\n";
    if (face) view.set_appearance(units.avatar, std::move(face));
  }
}

}  // namespace fw::client
