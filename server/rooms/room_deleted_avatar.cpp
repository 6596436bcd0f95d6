// Room (room.hpp): an avatar deleted by its uploader while people wear it.
// They stay, under a procedural face: the room's layout, their seat and
// their mood do not change, only the face the others see. The protocol
// already sends an avatar's package in chunks and clients put a new full
// package in place of the one they hold, so nothing new goes on the wire.
#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "demo_room.hpp"
#include "room.hpp"

namespace fw::server {

namespace net = boost::asio;

void Room::replace_deleted_avatar(std::string asset) {
  net::post(strand_, [self = shared_from_this(), asset = std::move(asset)] {
    if (self->closed_ || self->context_.demo_avatars.empty()) return;
    for (auto& [id, member] : self->members_) {
      if (member.info.asset != asset) continue;
      const StoredAvatar& face = procedural_face_for(self->context_, member.info.name);
      member.avatar = face;
      member.info.asset = face.asset;
      member.info.preview_bytes = static_cast<std::uint32_t>(face.preview ? face.preview->size() : 0);
      member.info.full_bytes = static_cast<std::uint32_t>(face.full ? face.full->size() : 0);
      for (auto& [viewer_id, viewer] : self->members_)
        if (viewer.stream) viewer.stream->replace_package(id, face.preview, face.full);
      // Whoever takes the room over, or welcomes a newcomer on another node, names the new face.
      if (self->role_ == RoomRole::owner) self->keep(member);
      spdlog::info("room {}: {} wears a procedural face from now on: their avatar {} was deleted", self->name_,
                   member.info.name, asset);
    }
  });
}

}  // namespace fw::server
