// The fit of the generic face to a person's landmarks: exact on the
// template, and never folded, whatever the landmarks.
#include "mesh_fitting.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "template_landmarks.hpp"

namespace fw::photo {
namespace {

std::vector<std::string> folds(const MeshFit& fit) {
  const model::GenericFace& generic = model::generic_face();
  return model::validate_generic_face(model::fit_generic_face(generic, fit.fitted_xy));
}

TEST(FitMesh, TheTemplatesOwnLandmarksGiveTheGenericFace) {
  const model::GenericFace& generic = model::generic_face();
  std::string note;
  const MeshFit fit = fit_mesh(generic, template_landmarks(), note);
  EXPECT_TRUE(note.empty()) << note;
  float worst = 0;
  for (std::size_t v = 0; v < fit.fitted_xy.size(); ++v)
    worst = std::max(worst, glm::length(fit.fitted_xy[v] - glm::vec2(generic.skin.positions[v])));
  EXPECT_LT(worst, 0.02f);
}

// Closed lips meet in the fit, so that at rest no slit shows the mouth's
// inside; lips that are parted stay parted, and neither folds the mesh.
TEST(FitMesh, ClosedLipsMeetAndPartedLipsStayApart) {
  const model::GenericFace& generic = model::generic_face();
  const auto vertex = [&](int landmark) { return generic.landmark_vertices[static_cast<std::size_t>(landmark)]; };
  std::string note;
  const MeshFit closed = fit_mesh(generic, template_landmarks(), note);
  for (const auto& [upper, lower] : {std::pair{61, 67}, {62, 66}, {63, 65}})
    EXPECT_EQ(closed.fitted_xy[vertex(upper)], closed.fitted_xy[vertex(lower)]) << upper << " and " << lower;
  ModelLandmarks parted = template_landmarks();
  for (const int lower : {65, 66, 67}) parted[static_cast<std::size_t>(lower)].y -= 0.15f;
  const MeshFit open = fit_mesh(generic, parted, note);
  EXPECT_NEAR(open.fitted_xy[vertex(62)].y - open.fitted_xy[vertex(66)].y,
              parted[62].y - parted[66].y, 1e-4f);
  for (const MeshFit* fit : {&closed, &open}) {
    const auto problems = folds(*fit);
    EXPECT_TRUE(problems.empty()) << problems.front();
  }
}

// Landmarks that cross each other fold any mesh pinned to them; the fit
// gives up some of their shape instead of refusing the photo.
TEST(FitMesh, CrossedLandmarksAreFittedWithoutAFoldAndSaySo) {
  const model::GenericFace& generic = model::generic_face();
  for (const auto& [a, b] : {std::pair{48, 54}, {30, 8}, {36, 45}}) {
    SCOPED_TRACE(std::to_string(a) + " and " + std::to_string(b) + " swapped");
    ModelLandmarks crossed = template_landmarks();
    std::swap(crossed[static_cast<std::size_t>(a)], crossed[static_cast<std::size_t>(b)]);
    std::string note;
    const MeshFit fit = fit_mesh(generic, crossed, note);
    const auto problems = folds(fit);
    EXPECT_TRUE(problems.empty()) << problems.front();
    EXPECT_NE(note.find("toward the generic face"), std::string::npos) << note;
  }
}

// One landmark far off (a misplaced lip point) bends the mesh; it may be
// smoothed, but it does not fold.
TEST(FitMesh, AStrayLandmarkDoesNotFoldTheMesh) {
  const model::GenericFace& generic = model::generic_face();
  ModelLandmarks stray = template_landmarks();
  stray[62] += glm::vec2(0.05f, 0.45f);  // the upper inner lip up past the nose tip
  std::string note;
  const MeshFit fit = fit_mesh(generic, stray, note);
  const auto problems = folds(fit);
  EXPECT_TRUE(problems.empty()) << problems.front();
}

}  // namespace
}  // namespace fw::photo
