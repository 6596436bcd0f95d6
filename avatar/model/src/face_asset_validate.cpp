#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

#include "fw/model/depth_profile.hpp"
#include "fw/model/face_asset.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::model {
namespace {

// Smaller than any triangle the generator makes (about 1e-3), larger than
// rounding noise: a triangle below it is a sliver that renders as a crack.
constexpr float kMinTriangleArea = 1e-5f;

float signed_area(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return 0.5f * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

void check_layer(const Mesh& mesh, const std::string& name, std::vector<std::string>& problems) {
  if (mesh.triangles.empty()) problems.push_back(name + " has no triangles");
  if (mesh.uvs.size() != mesh.positions.size())
    problems.push_back(name + " has " + std::to_string(mesh.uvs.size()) + " uvs for " +
                       std::to_string(mesh.positions.size()) + " positions");
  for (const glm::uvec3& t : mesh.triangles)
    if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size()) {
      problems.push_back(name + " has a triangle index out of range");
      return;
    }
}

std::set<std::uint32_t> as_set(const std::vector<std::uint32_t>& v) { return {v.begin(), v.end()}; }

void check_skin_triangles(const GenericFace& face, std::vector<std::string>& problems) {
  const Mesh& skin = face.skin;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t f = 0; f < skin.triangles.size(); ++f) {
    const glm::uvec3 t = skin.triangles[f];
    const std::string where = "skin triangle " + std::to_string(f);
    if (t.x == t.y || t.y == t.z || t.x == t.z) {
      problems.push_back(where + " repeats a vertex");
      continue;
    }
    // The skin is a frontal surface: seen from the front every triangle runs
    // counter-clockwise, in space and in the texture.
    const float area = signed_area(skin.positions[t.x], skin.positions[t.y], skin.positions[t.z]);
    if (std::abs(area) < kMinTriangleArea) problems.push_back(where + " is degenerate");
    else if (area < 0) problems.push_back(where + " is flipped");
    if (signed_area(skin.uvs[t.x], skin.uvs[t.y], skin.uvs[t.z]) <= 0)
      problems.push_back(where + " is flipped in the texture");
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed)
    if (count > 1)
      problems.push_back("skin edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                         " is used twice in one direction (inconsistent winding or non-manifold)");
  for (const glm::vec2& uv : skin.uvs)
    if (uv.x < 0 || uv.x > 1 || uv.y < 0 || uv.y > 1) {
      problems.push_back("a skin uv lies outside [0,1]");
      break;
    }
}

void check_holes(const GenericFace& face, std::vector<std::string>& problems) {
  const auto loops = boundary_loops(face.skin);
  if (loops.size() != 4) {
    problems.push_back("the skin has " + std::to_string(loops.size()) +
                       " boundary loops; expected 4 (outline, two eye holes, mouth slit)");
    return;
  }
  std::set<std::set<std::uint32_t>> loop_sets;
  for (const auto& loop : loops) loop_sets.insert(as_set(loop));
  const std::pair<const std::vector<std::uint32_t>*, const char*> holes[] = {
      {&face.eye_holes[0], "right eye hole"}, {&face.eye_holes[1], "left eye hole"},
      {&face.mouth_slit, "mouth slit"}};
  for (const auto& [hole, name] : holes)
    if (!loop_sets.contains(as_set(*hole))) problems.push_back(std::string("the ") + name + " is not a boundary loop of the skin");

  // The holes must be the ones the landmarks outline.
  const auto contains_landmarks = [&](const std::vector<std::uint32_t>& hole, int begin, int end) {
    const auto members = as_set(hole);
    for (int i = begin; i < end; ++i)
      if (!members.contains(face.landmark_vertices[static_cast<std::size_t>(i)])) return false;
    return true;
  };
  if (!contains_landmarks(face.eye_holes[0], landmarks::kEyeRightBegin, landmarks::kEyeRightEnd))
    problems.push_back("the right eye hole does not run through landmarks 36-41");
  if (!contains_landmarks(face.eye_holes[1], landmarks::kEyeLeftBegin, landmarks::kEyeLeftEnd))
    problems.push_back("the left eye hole does not run through landmarks 42-47");
  if (!contains_landmarks(face.mouth_slit, landmarks::kInnerLipBegin, landmarks::kInnerLipEnd))
    problems.push_back("the mouth slit does not run through landmarks 60-67");
}

// Whether `p` lies within the face's rim as seen from the front, and just
// behind the face (not as far back as the back of the head): where the face
// itself hides it from every view.
bool behind_face(glm::vec3 p, glm::vec2 centre, std::span<const glm::vec2> rim) {
  constexpr float kMaxDepthBehind = 1.6f;  // model units, 100 mm; the back of the head is further
  const glm::vec2 d = glm::vec2(p) - centre;
  const float depth = face_depth(glm::vec2(p));
  return glm::length(d) < ray_exit_radius(centre, std::atan2(d.y, d.x), rim) && p.z < depth &&
         p.z > depth - kMaxDepthBehind;
}

// The head shell must be closed wherever it can be seen: with coincident
// vertices welded (those along the silhouette are copied for a texture seam), every
// edge is shared by exactly two triangles, once in each direction, except
// around an opening behind the face. Anything else leaves a hole the
// background shows through when the head turns.
void check_head(const HeadShell& head, const Mesh& skin, std::vector<std::string>& problems) {
  if (head.outline.empty() || std::any_of(head.outline.begin(), head.outline.end(), [](float r) { return !(r > 0); }))
    problems.push_back("the head's outline is empty or not positive");
  std::map<std::tuple<float, float, float>, std::uint32_t> ids;
  std::vector<std::uint32_t> welded;
  for (const glm::vec3& p : head.mesh.positions)
    welded.push_back(ids.emplace(std::tuple{p.x, p.y, p.z}, static_cast<std::uint32_t>(ids.size())).first->second);
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const glm::uvec3& t : head.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::pair edge{welded[t[k]], welded[t[(k + 1) % 3]]};
      if (edge.first == edge.second || !directed.insert(edge).second) {
        problems.push_back("the head has a degenerate or non-manifold triangle");
        return;
      }
    }
  std::vector<glm::vec2> rim;
  for (std::uint32_t v : face_rim_loop(skin)) rim.emplace_back(skin.positions[v]);
  std::vector<glm::vec3> welded_positions(ids.size());
  for (const auto& [p, id] : ids) welded_positions[id] = {std::get<0>(p), std::get<1>(p), std::get<2>(p)};
  for (const auto& [a, b] : directed)
    if (!directed.contains({b, a}) && !(behind_face(welded_positions[a], head.centre, rim) &&
                                        behind_face(welded_positions[b], head.centre, rim))) {
      problems.push_back("the head is not closed (edge " + std::to_string(a) + "-" + std::to_string(b) +
                         " is open where it can be seen)");
      return;
    }
}

// The corrective components (at most codec::kCorrectiveCount): each a
// finite vertex field over the whole skin that moves something, no farther
// than an action unit may, and slides no texture.
void check_correctives(const GenericFace& face, std::vector<std::string>& problems) {
  const std::size_t vertex_count = face.skin.positions.size();
  if (face.correctives.size() > codec::kCorrectiveCount)
    problems.push_back("the face has " + std::to_string(face.correctives.size()) + " corrective components, at most " +
                       std::to_string(codec::kCorrectiveCount) + " fit the stream");
  for (std::size_t k = 0; k < face.correctives.size(); ++k) {
    const Morph& m = face.correctives[k];
    const std::string name = "corrective component " + std::to_string(k);
    if (m.vertex_delta.size() != vertex_count) {
      problems.push_back(name + " does not cover every skin vertex");
      continue;
    }
    if (std::any_of(m.uv_delta.begin(), m.uv_delta.end(), [](glm::vec2 t) { return t != glm::vec2(0.0f); }))
      problems.push_back(name + " slides the texture; a corrective moves vertices only");
    bool moves = false;
    for (std::size_t v = 0; v < vertex_count; ++v) {
      if (!(glm::length(m.vertex_delta[v]) < 1.0f)) {
        problems.push_back(name + " moves vertex " + std::to_string(v) + " implausibly far");
        break;
      }
      moves = moves || m.vertex_delta[v] != glm::vec3(0.0f);
    }
    if (!moves) problems.push_back(name + " moves no vertex");
  }
}

}  // namespace

std::vector<std::string> validate_generic_face(const GenericFace& face) {
  std::vector<std::string> problems;
  if (!(face.texture_frame.size > 0)) problems.push_back("texture_frame.size is not positive");
  check_layer(face.skin, "the skin", problems);
  check_layer(face.mouth_cavity, "the mouth cavity", problems);
  check_layer(face.head.mesh, "the head", problems);
  for (int side = 0; side < 2; ++side) {
    const EyeLayer& eye = face.eyes[static_cast<std::size_t>(side)];
    const std::string name = side ? "the left eyeball" : "the right eyeball";
    check_layer(eye.mesh, name, problems);
    if (!(eye.radius > 0) || !(eye.cap_angle_rad > 0)) problems.push_back(name + " has no size");
  }
  if (!problems.empty()) return problems;  // indices unsafe to follow

  const std::size_t vertex_count = face.skin.positions.size();
  std::set<std::uint32_t> anchors;
  for (std::uint32_t v : face.landmark_vertices) {
    if (v >= vertex_count) {
      problems.push_back("a landmark vertex index is out of range");
      return problems;
    }
    anchors.insert(v);
  }
  if (anchors.size() != face.landmark_vertices.size())
    problems.push_back("two landmarks share one vertex");
  for (const auto* hole : {&face.eye_holes[0], &face.eye_holes[1], &face.mouth_slit})
    if (std::any_of(hole->begin(), hole->end(), [&](std::uint32_t v) { return v >= vertex_count; })) {
      problems.push_back("a hole vertex index is out of range");
      return problems;
    }
  if (face.triangle_regions.size() != face.skin.triangles.size())
    problems.push_back(std::to_string(face.triangle_regions.size()) + " triangle regions for " +
                       std::to_string(face.skin.triangles.size()) + " skin triangles");
  for (FaceRegion r : face.triangle_regions)
    if (static_cast<std::size_t>(r) >= kFaceRegionCount) {
      problems.push_back("a triangle has no valid region");
      break;
    }
  check_skin_triangles(face, problems);
  check_holes(face, problems);
  check_head(face.head, face.skin, problems);
  for (std::size_t c = 0; c < face.action_units.size(); ++c) {
    const Morph& m = face.action_units[c];
    const std::string name = "action unit " + std::to_string(codec::kAuChannels[c].au);
    if (m.vertex_delta.size() != vertex_count || m.uv_delta.size() != vertex_count) {
      problems.push_back(name + " does not cover every skin vertex");
      continue;
    }
    // A unit moves skin by centimetres, never by a head's width.
    for (std::size_t v = 0; v < vertex_count; ++v)
      if (!(glm::length(m.vertex_delta[v]) < 1.0f) || !(glm::length(m.uv_delta[v]) < 0.25f)) {
        problems.push_back(name + " moves vertex " + std::to_string(v) + " implausibly far");
        break;
      }
  }
  check_correctives(face, problems);
  return problems;
}

}  // namespace fw::model
