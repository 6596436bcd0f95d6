#pragma once
// The head's pose in the photo, and the face as it would look frontal.
//
// A scaled-orthographic camera (rotation, scale, shift in the image plane)
// and a shape mode of the generic face (its height, above and below the
// eyes) are fitted to the inner face's landmarks against the generic face's
// 3D landmark anchors, as 3D-morphable-model fitters do. The depth of the
// relief stays the generic face's: in one view it cannot be told from the
// turn of the head. What the camera and the modes cannot
// explain is the person's own shape: it is turned back into the frontal
// view, so that a head turned 30 degrees gives the same frontal landmarks
// as the same head facing the camera.
#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

struct HeadPose {
  glm::mat3 rotation{1.0f};  ///< model frame -> camera frame (x right, y up, z toward the camera)
  float scale = 1.0f;        ///< model units -> aligned-frame units
  glm::vec2 shift{0.0f};     ///< aligned frame
  float height_mode = 0;     ///< relative stretch of the face along y
  float yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< for people: + yaw turns toward the person's left

  /// Where a model-frame 3D point appears in the aligned frame (the photo
  /// after the eye alignment: eyes near (+-0.5, 0), y up).
  glm::vec2 project(glm::vec3 model_point) const;
  /// The camera-facing part of a model-frame direction (1 faces the camera).
  float facing(glm::vec3 model_normal) const;
};

struct PoseFit {
  HeadPose pose;
  /// The landmarks as the head would show them facing the camera, in the
  /// model frame (eye centres at (+-0.5, 0)).
  ModelLandmarks frontal{};
  /// The 3D point of the person's face behind a frontal model-frame point.
  glm::vec3 surface(glm::vec2 frontal_point) const;

  // The frontal frame is the fit's own frame made to put the eye centres at
  // (+-0.5, 0): fit point = frontal_to_fit * (frontal point - frontal_origin).
  glm::mat2 frontal_to_fit{1.0f};
  glm::vec2 frontal_origin{0.0f};
  glm::vec2 to_fit_frame(glm::vec2 frontal_point) const;
};

/// Fits pose and shape to `aligned` (the landmarks after the eye alignment).
PoseFit fit_head_pose(const model::GenericFace& generic, const ModelLandmarks& aligned);

}  // namespace fw::photo
