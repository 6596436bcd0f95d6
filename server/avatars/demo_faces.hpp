#pragma once
// Avatar packages made by the project itself for the demo room: procedural
// faces on the generic face, with different skin tones, eye and hair colours,
// since a fresh clone has no photos. Also the face of a client that joins
// without an uploaded package.
#include <cstdint>
#include <vector>

namespace fw::server {

/// A valid .fwa for look number `index` (0, 1, 2 are the lobby's three;
/// any index gives some face).
std::vector<std::uint8_t> make_demo_package(std::uint32_t index);

}  // namespace fw::server
