#include "resident_faces.hpp"

#include <array>

namespace fw::embedded {
// server/avatars/residents/*.fwa, compiled in by server/avatars/CMakeLists.txt.
extern const std::string_view resident_ada;
extern const std::string_view resident_bruno;
extern const std::string_view resident_grace;
}  // namespace fw::embedded

namespace fw::server {

std::span<const ResidentFace> resident_faces() {
  // The names are the residents' own, not the photographed people's: the
  // residents are characters who wear those faces (their words and moods are
  // the simulation's). Ada leads the lobby's conversation.
  static const std::array<ResidentFace, 3> kResidents = {{
      {"Ada", "tests/data/astronaut.png", embedded::resident_ada},
      {"Bruno", "tests/data/kphotoalbum_jesper.jpg", embedded::resident_bruno},
      {"Grace", "tests/data/grace_hopper.jpg", embedded::resident_grace},
  }};
  return kResidents;
}

}  // namespace fw::server
