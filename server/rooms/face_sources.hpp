#pragma once
// Each face of a room as its viewers' encoders see it (codec::FaceSource),
// worked out once a tick for all of them: every viewer holds an encoder per
// face, and turning the face into coded channels, with the two ticks before
// for the motion estimate, is the same work for each. A room of 10 did it
// 100 times a tick; now 10. The frames are byte for byte what each encoder
// makes from the face itself (tests/server/rooms/face_sources_test.cpp).
#include <cstdint>
#include <map>
#include <span>

#include "fw/codec/codec.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {

class FaceSources {
 public:
  /// Offers this tick's faces to their sources and points each entry of
  /// `faces` at its own; the sources of faces no longer there go.
  void offer(std::span<AvatarFace> faces);
  std::size_t size() const { return sources_.size(); }

 private:
  std::map<std::uint32_t, codec::FaceSource> sources_;
};

}  // namespace fw::server
