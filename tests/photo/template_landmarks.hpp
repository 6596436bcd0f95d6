#pragma once
// The generic face's own 68 landmarks, as a fit takes them: a neutral
// person who looks exactly like the template.
#include <algorithm>

#include "fw/model/landmark_template.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

inline ModelLandmarks template_landmarks() {
  ModelLandmarks landmarks{};
  const auto generic = model::landmark_template();
  std::copy(generic.begin(), generic.end(), landmarks.begin());
  return landmarks;
}

}  // namespace fw::photo
