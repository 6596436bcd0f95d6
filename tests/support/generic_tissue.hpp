#pragma once
// The generic face's tissue model, built once per test process (it takes a
// moment) and shared by the physics tests.
#include <memory>

#include "fw/model/generic_face.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::test {

inline std::shared_ptr<const physics::TissueModel> generic_tissue() {
  static const auto tissue = physics::build_tissue_model(model::generic_face(), model::generic_face().action_units);
  return tissue;
}

}  // namespace fw::test
