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
    codec::FaceSource& source = sources_[face.id];
    source.offer(*face.face);
    face.source = &source;
  }
}

}  // namespace fw::server
