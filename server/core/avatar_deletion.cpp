#include "avatar_deletion.hpp"

#include <algorithm>

#include "room.hpp"
#include "room_registry.hpp"
#include "server_keys.hpp"

namespace fw::server {

AvatarDeletion delete_avatar(ServerContext& context, const std::string& asset, std::string_view key) {
  const AvatarStatus status = context.store->lookup(asset).status;
  if (status == AvatarStatus::unknown || status == AvatarStatus::deleted) return AvatarDeletion::unknown;
  // Their keys were handed to anyone who uploaded their bytes before ids
  // were random; and every server makes them again at its start anyway.
  if (std::any_of(context.demo_avatars.begin(), context.demo_avatars.end(),
                  [&](const StoredAvatar& face) { return face.asset == asset; }))
    return AvatarDeletion::server_face;
  if (key.empty()) return AvatarDeletion::no_key;
  if (!avatar_key_matches(context.server_key, asset, key)) return AvatarDeletion::wrong_key;
  context.store->remove(asset);
  replace_deleted_avatar_in_rooms(context, asset);
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

void replace_deleted_avatar_in_rooms(ServerContext& context, const std::string& asset) {
  if (!context.rooms) return;
  for (const auto& room : context.rooms->all()) room->replace_deleted_avatar(asset);
}

}  // namespace fw::server
