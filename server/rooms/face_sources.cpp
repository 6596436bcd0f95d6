#include "face_sources.hpp"

#include <algorithm>

namespace fw::server {

void FaceSources::offer(std::span<AvatarFace> faces) {
  // A face gone (its avatar left) loses its history: one that comes back
  // starts afresh, as a new encoder would.
  std::erase_if(sources_, [faces](const auto& entry) {
    return std::none_of(faces.begin(), faces.end(), [&](const AvatarFace& f) { return f.id == entry.first; });
  });
  for (AvatarFace& face : faces) {
    Face& own = sources_[face.id];
    own.source.offer(*face.face);
    face.source = &own.source;
    face.encoders = &own.encoders;
  }
}

std::size_t FaceSources::shared_encoders() {
  std::size_t groups = 0;
  for (auto& [id, face] : sources_) groups += face.encoders.groups();
  return groups;
}

}  // namespace fw::server
