#include "fw/model/generic_face.hpp"

namespace fw::model {

std::optional<FaceRegion> face_region_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kFaceRegionNames.size(); ++i)
    if (kFaceRegionNames[i] == name) return static_cast<FaceRegion>(i);
  return std::nullopt;
}

}  // namespace fw::model
