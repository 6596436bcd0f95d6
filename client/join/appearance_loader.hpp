#pragma once
// Turns the packages the session puts into the RoomState into faces for the
// RoomView: each avatar's newest package (the preview, then the full one)
// is parsed and fitted once, on the render thread and off the state's lock,
// since that takes milliseconds, and drawn with the units its person
// redefined (redefined_faces.hpp). A package that cannot be shown leaves the
// avatar drawn as the generic face.
#include <cstdint>
#include <map>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

#include "redefined_faces.hpp"
#include "room_state.hpp"
#include "room_view.hpp"

namespace fw::client {

class AppearanceLoader {
 public:
  /// Problems (a package that does not parse) are written to `log`.
  explicit AppearanceLoader(std::ostream& log) : log_(log) {}

  using Package = std::pair<std::uint32_t, std::shared_ptr<const std::vector<std::uint8_t>>>;
  /// What changed since the last call: the packages that arrived, by
  /// avatar, the newest redefined units of those whose units changed, and
  /// who left. Holds `state.mutex` while it looks.
  struct Changes {
    std::vector<Package> packages;
    std::vector<codec::UnitMorphs> units;
    std::vector<std::uint32_t> gone;
  };
  Changes take_new(RoomState& state);
  /// Gives `view` the faces of the packages and units that arrived since the last call.
  void load_new(RoomState& state, RoomView& view);

 private:
  std::ostream& log_;
  std::map<std::uint32_t, std::uint64_t> loaded_;  ///< avatar -> package_serial shown
  std::map<std::uint32_t, std::uint32_t> units_loaded_;  ///< avatar -> version of its units shown
  RedefinedFaces faces_;
};

}  // namespace fw::client
