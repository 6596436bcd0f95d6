#include "fw/model/generic_face.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

#include "fw/model/face_asset.hpp"

namespace fw::embedded {
extern const std::string_view generic_face_json;  // assets/generic_face.json, see CMakeLists.txt
}

namespace fw::model {

const GenericFace& generic_face() {
  static const GenericFace face = [] {
    GenericFace parsed;
    std::string error;
    if (!parse_face_asset(embedded::generic_face_json, parsed, error)) {
      // The embedded asset is validated by the test suite; reaching this is a
      // broken build, not bad input.
      std::cerr << "facewire: " << error << " (rebuild with `make facegen`)\n";
      std::abort();
    }
    return parsed;
  }();
  return face;
}

std::string_view generic_face_asset_json() { return embedded::generic_face_json; }

}  // namespace fw::model
