// Fuzzes parse_face_asset: any input must give either an error message or a
// face that passes validation, without crashing, hanging or leaking.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fw/model/face_asset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fw::model::GenericFace face;
  std::string error;
  const bool ok = fw::model::parse_face_asset(std::string_view(reinterpret_cast<const char*>(data), size), face, error);
  if (ok != error.empty()) std::abort();  // exactly one of: a face, or a reason
  if (ok && !fw::model::validate_generic_face(face).empty()) std::abort();
  return 0;
}
