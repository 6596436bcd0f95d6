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

/// The landmarks as the fit uses them: inner lips that are closed (closer
/// than the template's closed slit and a little more, or crossed, as dlib
/// often puts closed lips) made to meet, each pair at its middle, so that
/// the mouth slit is shut at rest. Parted lips are kept as they are.
ModelLandmarks landmarks_for_fit(const ModelLandmarks& landmarks);

/// Fits the generic face to the landmarks, never folding a triangle: the
/// spline through them, else a smoother one, else one through landmarks
/// drawn part of the way toward the generic face's own (at worst all the
/// way, which fits exactly). Once a face is found, the fit never fails;
/// `note` says what was given up, if anything.
MeshFit fit_mesh(const model::GenericFace& generic, const ModelLandmarks& landmarks, std::string& note);

}  // namespace fw::photo
