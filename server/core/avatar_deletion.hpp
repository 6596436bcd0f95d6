#pragma once
// An uploader deleting their avatar (DELETE /api/avatars/ID, PROTOCOL.md 8):
// who may, and what follows. No sockets here: rest_api.cpp answers with
// what this decides, and a cluster node calls the second half when another
// node deleted one (cluster_node_avatars.cpp).
#include <string>
#include <string_view>
#include <vector>

#include "avatar_store.hpp"

namespace fw::server {

class RoomRegistry;

/// What deciding a deletion reads, and what it changes.
struct AvatarDeletionServices {
  AvatarStore& store;
  RoomRegistry& rooms;  ///< whoever wears the avatar here is shown another face
  /// The server's own faces: nobody's to delete; one replaces the avatar deleted.
  const std::vector<StoredAvatar>& own_faces;
  const std::string& server_key;  ///< signs avatar keys (server_keys.hpp)
};

enum class AvatarDeletion {
  deleted,      ///< gone here and from the cluster's copy; its wearers wear procedural faces
  unknown,      ///< no avatar has this id (never uploaded, or deleted already)
  no_key,       ///< the request shows no key
  wrong_key,    ///< the key is not this avatar's
  server_face,  ///< one of the server's own faces, nobody's to delete
};

/// Whether a request that shows `key` comes from the owner of avatar
/// `asset` (deletion, saved looks): `deleted` stands for "yes, its owner";
/// else why not, as a deletion would be answered.
AvatarDeletion check_avatar_owner(const AvatarDeletionServices& services, const std::string& asset,
                                  std::string_view key);

/// Deletes the avatar `asset` (package, preview, photo) if `key` is its
/// key (server_keys.hpp: the one its upload answered).
AvatarDeletion delete_avatar(const AvatarDeletionServices& services, const std::string& asset, std::string_view key);

/// What the person who asked is told: what happened, or what was wrong
/// and what to do.
std::string deletion_message(AvatarDeletion outcome, const std::string& asset);

/// The avatar `asset` is gone (deleted here, or on another node): whoever
/// wears it in this node's rooms is shown with a procedural face from now on.
void replace_deleted_avatar_in_rooms(RoomRegistry& rooms, const std::string& asset);

}  // namespace fw::server
