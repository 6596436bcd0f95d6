#pragma once
// Turns the packages the session puts into the RoomState into faces for the
// RoomView: each avatar's newest package (the preview, then the full one)
// is parsed and fitted once, on the render thread and off the state's lock,
// since that takes milliseconds. A package that cannot be shown leaves the
// avatar drawn as the generic face.
#include <cstdint>
#include <map>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

#include "room_state.hpp"
#include "room_view.hpp"

namespace fw::client {

class AppearanceLoader {
 public:
  /// Problems (a package that does not parse) are written to `log`.
  explicit AppearanceLoader(std::ostream& log) : log_(log) {}

  using Package = std::pair<std::uint32_t, std::shared_ptr<const std::vector<std::uint8_t>>>;
  /// The packages that arrived since the last call, by avatar; holds
  /// `state.mutex` while it looks.
  std::vector<Package> take_new(RoomState& state);
  /// Gives `view` the faces of the packages that arrived since the last call.
  void load_new(RoomState& state, RoomView& view);

 private:
  std::ostream& log_;
  std::map<std::uint32_t, std::uint64_t> loaded_;  ///< avatar -> package_serial shown
};

}  // namespace fw::client
