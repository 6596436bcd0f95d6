#pragma once
// A request to seat someone in a room: a person connected here, one
// bridged from another node of a cluster, or one of the room's own
// autonomous avatars.
#include <memory>
#include <string>

#include "avatar_store.hpp"
#include "room_connection.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {

struct JoinRequest {
  std::string name;
  StoredAvatar avatar;
  StreamSettings stream;
  std::shared_ptr<RoomConnection> connection;  ///< null for the room's own autonomous avatars
  std::string resume;  ///< the connection's resume key, for its welcome
  /// The person's address (address_key()), for the seats one address may
  /// hold; empty for autonomous avatars.
  std::string address;
  /// The resume key the hello showed (PROTOCOL.md 5.1): in a cluster, a
  /// person whose node died takes their seat back with it.
  std::string returning;
  // A join bridged from another node (cluster): that node and its reference.
  std::string node;
  std::string join_ref;
  std::string resume_hash;  ///< of `resume`, when the connection is on another node
  /// The language the person's lines are said in (PROTOCOL.md 5.1), checked
  /// by whoever took the hello; empty: the room's (autonomous avatars too).
  std::string language = {};
};

}  // namespace fw::server
