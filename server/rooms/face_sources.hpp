#pragma once
// Each face of a room as its viewers' encoders see it (codec::FaceSource),
// worked out once a tick for all of them: every viewer holds an encoder per
// face, and turning the face into coded channels, with the two ticks before
// for the motion estimate, is the same work for each. A room of 10 did it
// 100 times a tick; now 10. The frames are byte for byte what each encoder
// makes from the face itself (tests/server/rooms/face_sources_test.cpp).
// Each face also lists the encoders its viewers share (shared_encoder.hpp).
#include <cstdint>
#include <map>
#include <span>

#include "avatar_face.hpp"
#include "fw/codec/codec.hpp"
#include "shared_encoder.hpp"

namespace fw::server {

class FaceSources {
 public:
  /// Offers this tick's faces to their sources and points each entry of
  /// `faces` at its own source and shared encoders; those of faces no
  /// longer there go (their groups live on with their members until they
  /// drop the face).
  void offer(std::span<AvatarFace> faces);
  std::size_t size() const { return sources_.size(); }
  /// Groups of shared encoders, over all faces.
  std::size_t shared_encoders();

 private:
  struct Face {
    codec::FaceSource source;
    FaceEncoders encoders;
  };
  std::map<std::uint32_t, Face> sources_;
};

}  // namespace fw::server
