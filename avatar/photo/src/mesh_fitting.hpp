#pragma once
// Fitting the generic face to a person: a thin-plate spline from the
// template's 68 landmarks to the person's (model frame) moves every skin
// vertex; the landmark vertices land exactly on the landmarks.
#include <string>
#include <vector>

#include "fw/model/generic_face.hpp"
#include "fw/photo/prep_error.hpp"
#include "thin_plate_spline.hpp"

namespace fw::photo {

using ModelLandmarks = std::array<glm::vec2, model::kLandmarkCount>;  ///< model frame

struct MeshFit {
  std::vector<glm::vec2> fitted_xy;  ///< #V of the generic skin
  ThinPlateSpline warp;              ///< template frame -> this face
};

/// The landmarks as the fit uses them: the inner lips kept at least a slit
/// apart (dlib often puts closed lips on top of each other, which would
/// fold the mesh at the mouth).
ModelLandmarks landmarks_for_fit(const ModelLandmarks& landmarks);

/// Fits the generic face to the landmarks, never folding a triangle: the
/// spline through them, else a smoother one, else one through landmarks
/// drawn part of the way toward the generic face's own (at worst all the
/// way, which fits exactly). Once a face is found, the fit never fails;
/// `note` says what was given up, if anything.
MeshFit fit_mesh(const model::GenericFace& generic, const ModelLandmarks& landmarks, std::string& note);

}  // namespace fw::photo
