#include "appearance_loader.hpp"

#include "fw/model/avatar_package.hpp"
#include "fw/render/avatar_appearance.hpp"

namespace fw::client {

std::vector<AppearanceLoader::Package> AppearanceLoader::take_new(RoomState& state) {
  std::vector<Package> fresh;
  std::lock_guard lock(state.mutex);
  for (const auto& [id, avatar] : state.avatars) {
    if (!avatar.package) continue;
    auto& serial = loaded_[id];
    if (serial == avatar.package_serial) continue;
    serial = avatar.package_serial;
    fresh.emplace_back(id, avatar.package);
  }
  return fresh;
}

void AppearanceLoader::load_new(RoomState& state, RoomView& view) {
  for (const auto& [id, bytes] : take_new(state)) {
    model::AvatarPackage package;
    auto appearance = std::make_shared<render::AvatarAppearance>();
    std::string error;
    if (!model::parse_avatar_package(*bytes, package, error) ||
        !render::load_avatar_appearance(package, *appearance, error)) {
      log_ << "avatar " << id << ": its package cannot be shown (" << error << "); drawing the generic face\n";
      continue;
    }
    view.set_appearance(id, std::move(appearance));
  }
}

}  // namespace fw::client
