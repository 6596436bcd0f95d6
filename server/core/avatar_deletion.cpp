#include "avatar_deletion.hpp"

#include <algorithm>

#include "room.hpp"
#include "room_registry.hpp"
#include "server_keys.hpp"

namespace fw::server {

AvatarDeletion check_avatar_owner(const AvatarDeletionServices& services, const std::string& asset,
                                  std::string_view key) {
  const AvatarStatus status = services.store.lookup(asset).status;
  if (status == AvatarStatus::unknown || status == AvatarStatus::deleted) return AvatarDeletion::unknown;
  // Their keys were handed to anyone who uploaded their bytes before ids
  // were random; and every server makes them again at its start anyway.
  if (std::any_of(services.own_faces.begin(), services.own_faces.end(),
                  [&](const StoredAvatar& face) { return face.asset == asset; }))
    return AvatarDeletion::server_face;
  if (key.empty()) return AvatarDeletion::no_key;
  if (!avatar_key_matches(services.server_key, asset, key)) return AvatarDeletion::wrong_key;
  return AvatarDeletion::deleted;
}

AvatarDeletion delete_avatar(const AvatarDeletionServices& services, const std::string& asset, std::string_view key) {
  if (const AvatarDeletion owner = check_avatar_owner(services, asset, key); owner != AvatarDeletion::deleted)
    return owner;
  services.store.remove(asset);
  replace_deleted_avatar_in_rooms(services.rooms, asset);
  return AvatarDeletion::deleted;
}

std::string deletion_message(AvatarDeletion outcome, const std::string& asset) {
  const std::string id = asset.substr(0, 64);
  switch (outcome) {
    case AvatarDeletion::deleted: return "avatar " + id + " and its photo are deleted";
    case AvatarDeletion::unknown:
      return "no avatar '" + id + "' is stored here: it was deleted already, or never uploaded";
    case AvatarDeletion::no_key:
      return "deleting an avatar takes its key: send the 'key' its upload answered in an X-Avatar-Key header";
    case AvatarDeletion::wrong_key:
      return "that is not the key of avatar " + id +
             ": only whoever uploaded it may delete it, with the 'key' its upload answered";
    case AvatarDeletion::server_face: return "avatar " + id + " is one of the server's own faces; it cannot be deleted";
  }
  return {};
}

void replace_deleted_avatar_in_rooms(RoomRegistry& rooms, const std::string& asset) {
  for (const auto& room : rooms.all()) room->replace_deleted_avatar(asset);
}

}  // namespace fw::server
