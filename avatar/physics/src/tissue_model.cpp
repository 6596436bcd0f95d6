#include "fw/physics/tissue_model.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include <glm/geometric.hpp>

#include "fw/model/landmark_template.hpp"
#include "fw/model/mesh.hpp"
#include "fw/physics/muscle_course.hpp"
#include "fw/physics/muscle_profile.hpp"
#include "fw/physics/prism_volume.hpp"
#include "fw/physics/regional_thickness.hpp"

namespace fw::physics {
namespace {

using model::FaceRegion;

// Where each node layer lies, as a share of the column's thickness, and how
// close to the skull each may come (Lee et al. 1995 make the epidermis and
// dermis thin, the fat thick, the muscle layer between fascia and bone).
constexpr std::array<float, kTissueLayerCount> kLayerDepth = {0.0f, 0.15f, 0.4f, 0.65f, 1.0f};
constexpr std::array<float, kTissueLayerCount> kLayerMinHeight = {0.3f, 0.25f, 0.18f, 0.1f, 0.0f};

// The mandible turns about an axis along x through this point; the bone
// under the chin follows fully, the bone above the mouth not at all (the same
// hinge and heights as the face's geometric jaw units).
constexpr glm::vec3 kJawHinge{0.0f, -0.25f, 0.3f};
constexpr float kJawFullBelowY = -1.2f, kJawNoneAboveY = -1.03f;

// Opening the mouth wide, the condyles first turn in their sockets and then
// glide forward and down the articular eminence, 15-20 mm at full opening;
// the first 20-25 mm of incisal opening (about half of it) are rotation
// alone (Okeson, Management of Temporomandibular Disorders and Occlusion,
// ch. 1; the eminence slopes about 30 degrees below the horizontal). Here:
// 15 mm along a 30-degree slope at the jaw's widest, from half of it on.
constexpr float kCondyleGlideMm = 15.0f;
constexpr float kEminenceSlopeRad = 0.5236f;
constexpr float kGlideOnsetShare = 0.5f;

// A vertex on no triangle (none on a sound face) gets the face's mean depth.
constexpr float kFallbackThicknessMm = 10.0f;

struct EdgeInfo {
  std::uint32_t a, b;
  std::vector<std::uint32_t> opposite;  // the third vertex of each triangle on the edge
};

std::vector<EdgeInfo> mesh_edges(const model::Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> index;
  std::vector<EdgeInfo> edges;
  for (const glm::uvec3& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const auto key = std::minmax(a, b);
      auto [it, inserted] = index.try_emplace({key.first, key.second}, edges.size());
      if (inserted) edges.push_back({key.first, key.second, {}});
      edges[it->second].opposite.push_back(c);
    }
  }
  return edges;
}

// Vertex normals smoothed over their neighbours, so that columns under
// sharp features (nose tip, lip edges) converge less.
std::vector<glm::vec3> smooth_normals(const model::Mesh& mesh, const std::vector<EdgeInfo>& edges) {
  std::vector<glm::vec3> normals = model::vertex_normals(mesh);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<glm::vec3> sum = normals;
    for (const EdgeInfo& e : edges) {
      sum[e.a] += normals[e.b];
      sum[e.b] += normals[e.a];
    }
    for (std::size_t v = 0; v < normals.size(); ++v) {
      const float length = glm::length(sum[v]);
      normals[v] = length > 1e-12f ? sum[v] / length : glm::vec3(0, 0, 1);
    }
  }
  return normals;
}

float smoothstep(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

std::vector<float> column_jaw_shares(const model::GenericFace& face) {
  const std::size_t n = face.skin.positions.size();
  std::vector<std::set<FaceRegion>> regions(n);
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) regions[face.skin.triangles[f][k]].insert(face.triangle_regions[f]);
  std::vector<float> share(n);
  for (std::size_t v = 0; v < n; ++v) {
    const bool lower = regions[v].contains(FaceRegion::lower_lip), upper = regions[v].contains(FaceRegion::upper_lip);
    if (lower && upper) share[v] = 0.5f;
    else if (lower) share[v] = 1.0f;
    else if (upper) share[v] = 0.0f;
    else share[v] = smoothstep((kJawNoneAboveY - face.skin.positions[v].y) / (kJawNoneAboveY - kJawFullBelowY));
  }
  return share;
}

class Builder {
 public:
  Builder(const model::GenericFace& face, const TissueOptions& options, TissueModel& m)
      : face_(face), m_(m), edges_(mesh_edges(face.skin)) {
    m_.material = options.material;
    m_.vertex_count = static_cast<std::uint32_t>(face.skin.positions.size());
    m_.node_count = m_.vertex_count * kTissueLayerCount;
    m_.moving_node_count = m_.vertex_count * kMovingLayerCount;
    m_.layer_depth = kLayerDepth;
    m_.layer_min_height = kLayerMinHeight;
    m_.jaw_hinge = kJawHinge;
    m_.skull_normal = smooth_normals(face.skin, edges_);
    find_lip_columns();
    pair_inner_lips();
  }

  // The inner lip contour's landmarks (dlib's 60-67: the corners 60 and 64,
  // the upper edge 61-63, the lower 67-65 under them).
  void pair_inner_lips() {
    namespace lm = model::landmarks;
    for (int k = 1; k < 4; ++k) {
      const std::uint32_t upper = face_.landmark_vertices[lm::kInnerLipBegin + k];
      const std::uint32_t lower = face_.landmark_vertices[lm::kInnerLipEnd - k];
      m_.lip_pairs.push_back({static_cast<std::uint16_t>(upper), static_cast<std::uint16_t>(lower)});
    }
  }

  void build(const std::array<model::Morph, codec::kAuChannelCount>& basis) {
    place_nodes();
    add_springs();
    add_elements();
    add_jaw();
    pin_outline();
    add_muscles();
    add_bellies();
    copy_basis(basis);
    estimate_stable_substep();
    shrink();
  }

 private:
  std::uint16_t node(std::size_t layer, std::uint32_t v) const {
    return static_cast<std::uint16_t>(layer * m_.vertex_count + v);
  }
  glm::vec3 rest(std::size_t i) const { return {m_.rest_x[i], m_.rest_y[i], m_.rest_z[i]}; }

  void set_positions() {
    m_.rest_x.resize(m_.node_count);
    m_.rest_y.resize(m_.node_count);
    m_.rest_z.resize(m_.node_count);
    for (std::size_t layer = 0; layer < kTissueLayerCount; ++layer)
      for (std::uint32_t v = 0; v < m_.vertex_count; ++v) {
        const glm::vec3 p =
            face_.skin.positions[v] - m_.skull_normal[v] * (m_.column_thickness[v] * kLayerDepth[layer]);
        const std::size_t i = node(layer, v);
        m_.rest_x[i] = p.x;
        m_.rest_y[i] = p.y;
        m_.rest_z[i] = p.z;
      }
  }

  float prism_rest_volume(const glm::uvec3& t, std::size_t layer) const {
    PrismNodes p;
    for (int k = 0; k < 3; ++k) {
      p[static_cast<std::size_t>(k)] = rest(node(layer, t[k]));
      p[static_cast<std::size_t>(k + 3)] = rest(node(layer + 1, t[k]));
    }
    return prism_volume(p);
  }

  // Each column starts at its region's depth (regional_thickness.cpp), the
  // mean over the triangles around it, so that depths blend across region
  // borders; where columns converge (nose, lips, the rim turning back) the
  // tissue is made thinner until every prism keeps a healthy share of its
  // nominal volume.
  void place_nodes() {
    std::vector<float> sum(m_.vertex_count, 0.0f), count(m_.vertex_count, 0.0f);
    for (std::size_t f = 0; f < face_.skin.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        sum[face_.skin.triangles[f][k]] += regional_thickness_mm(face_.triangle_regions[f]);
        count[face_.skin.triangles[f][k]] += 1.0f;
      }
    m_.column_thickness.assign(m_.vertex_count, 0.0f);
    for (std::uint32_t v = 0; v < m_.vertex_count; ++v)
      m_.column_thickness[v] = (count[v] > 0.0f ? sum[v] / count[v] : kFallbackThicknessMm) / model::kMillimetresPerUnit;
    for (int pass = 0; pass < 40; ++pass) {
      set_positions();
      std::set<std::uint32_t> thin;
      for (const glm::uvec3& t : face_.skin.triangles) {
        const glm::vec3 a = face_.skin.positions[t[0]], b = face_.skin.positions[t[1]], c = face_.skin.positions[t[2]];
        const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
        const float h = (m_.column_thickness[t[0]] + m_.column_thickness[t[1]] + m_.column_thickness[t[2]]) / 3.0f;
        for (std::size_t layer = 0; layer + 1 < kTissueLayerCount; ++layer) {
          const float nominal_volume = area * h * (kLayerDepth[layer + 1] - kLayerDepth[layer]);
          if (prism_rest_volume(t, layer) < 0.5f * nominal_volume) thin.insert({t[0], t[1], t[2]});
        }
      }
      if (thin.empty()) return;
      for (std::uint32_t v : thin) m_.column_thickness[v] *= 0.85f;
    }
    set_positions();
  }

  // The mouth corners have no bone under them: the upper lip is tied to the
  // maxilla, the lower to the mandible, and the corners between them only
  // slide over the teeth, so the jaw carries them through the lips instead
  // of tearing them between upper and lower jaw.
  void find_lip_columns() {
    constexpr FaceRegion kLips[] = {FaceRegion::upper_lip, FaceRegion::lower_lip, FaceRegion::mouth_corner_left,
                                    FaceRegion::mouth_corner_right};
    std::vector<int> lip(m_.vertex_count, 1), corner(m_.vertex_count, 0);
    for (std::size_t f = 0; f < face_.skin.triangles.size(); ++f) {
      const FaceRegion r = face_.triangle_regions[f];
      const bool is_lip = std::find(std::begin(kLips), std::end(kLips), r) != std::end(kLips);
      const bool is_corner = r == FaceRegion::mouth_corner_left || r == FaceRegion::mouth_corner_right;
      for (int k = 0; k < 3; ++k) {
        if (!is_lip) lip[face_.skin.triangles[f][k]] = 0;
        if (is_corner) corner[face_.skin.triangles[f][k]] = 1;
      }
    }
    m_.column_on_bone.assign(m_.vertex_count, 1);
    for (std::uint32_t v = 0; v < m_.vertex_count; ++v) m_.column_on_bone[v] = lip[v] && corner[v] ? 0 : 1;
    // Nor do the alae and nostril sills: their frame is the alar cartilage,
    // which the levator labii superioris alaeque nasi lifts with them in AU 9
    // (tied to the bone, the ala's tissue sheared over a fixed frame until
    // its prisms turned inside out). The tip and the columella stay on the
    // septum.
    for (int l : {model::landmarks::kNoseBaseBegin, model::landmarks::kNoseBaseBegin + 1,
                  model::landmarks::kNoseBaseEnd - 2, model::landmarks::kNoseBaseEnd - 1})
      m_.column_on_bone[face_.landmark_vertices[static_cast<std::size_t>(l)]] = 0;
  }
  bool on_bone(std::uint32_t v) const { return m_.column_on_bone[v] != 0; }

  void add_spring(std::uint16_t a, std::uint16_t b, SpringKind kind) {
    m_.spring_a.push_back(a);
    m_.spring_b.push_back(b);
    m_.spring_rest.push_back(glm::length(rest(a) - rest(b)));
    m_.spring_kind.push_back(kind);
  }

  void add_springs() {
    constexpr std::array<SpringKind, kMovingLayerCount> kLayerKind = {SpringKind::epidermis, SpringKind::dermis,
                                                                     SpringKind::fat, SpringKind::fascia};
    for (std::size_t layer = 0; layer < kMovingLayerCount; ++layer)
      for (const EdgeInfo& e : edges_) add_spring(node(layer, e.a), node(layer, e.b), kLayerKind[layer]);
    for (std::size_t layer = 0; layer < kMovingLayerCount; ++layer) {
      const bool muscle = layer + 1 == kMovingLayerCount;
      for (std::uint32_t v = 0; v < m_.vertex_count; ++v)
        if (!muscle || on_bone(v))
          add_spring(node(layer, v), node(layer + 1, v), muscle ? SpringKind::column_muscle : SpringKind::column_skin);
      for (const EdgeInfo& e : edges_) {
        const SpringKind kind = muscle ? SpringKind::shear_muscle : SpringKind::shear_skin;
        if (!muscle || on_bone(e.b)) add_spring(node(layer, e.a), node(layer + 1, e.b), kind);
        if (!muscle || on_bone(e.a)) add_spring(node(layer, e.b), node(layer + 1, e.a), kind);
      }
    }
    for (const EdgeInfo& e : edges_)
      if (e.opposite.size() == 2) add_spring(node(0, e.opposite[0]), node(0, e.opposite[1]), SpringKind::bending);
  }

  void add_elements() {
    for (const glm::uvec3& t : face_.skin.triangles) {
      const glm::vec3 a = face_.skin.positions[t[0]], b = face_.skin.positions[t[1]], c = face_.skin.positions[t[2]];
      m_.skin_triangles.push_back(t);
      m_.skin_rest_area.push_back(0.5f * glm::length(glm::cross(b - a, c - a)));
      const bool free_of_bone = !on_bone(t[0]) || !on_bone(t[1]) || !on_bone(t[2]);
      for (std::size_t layer = 0; layer + 1 < kTissueLayerCount; ++layer) {
        if (layer + 1 == kMovingLayerCount && free_of_bone) continue;
        std::array<std::uint16_t, 6> nodes{};
        PrismNodes p;
        for (int k = 0; k < 3; ++k) {
          nodes[static_cast<std::size_t>(k)] = node(layer, t[k]);
          nodes[static_cast<std::size_t>(k + 3)] = node(layer + 1, t[k]);
        }
        for (std::size_t k = 0; k < 6; ++k) p[k] = rest(nodes[k]);
        PrismNodes gradient;
        const float volume = prism_volume(p, &gradient);
        float mean = 0.0f;
        for (const glm::vec3& g : gradient) mean += glm::length(g) / 6.0f;
        for (std::size_t k = 0; k < 6; ++k) m_.element_node[k].push_back(nodes[k]);
        m_.element_rest_volume.push_back(volume);
        const float area = m_.skin_rest_area.back();
        m_.element_force_scale.push_back(mean > 0.0f && area > 0.0f ? 1.0f / (mean * area) : 0.0f);
      }
    }
  }

  void add_jaw() {
    m_.jaw_share = column_jaw_shares(face_);
    const float glide = kCondyleGlideMm / model::kMillimetresPerUnit;
    m_.jaw_glide = glide * glm::vec3(0.0f, -std::sin(kEminenceSlopeRad), std::cos(kEminenceSlopeRad));
    m_.jaw_glide_onset_rad = kGlideOnsetShare * m_.jaw_max_rad;
  }

  // The bellies of the muscles that bulge (the masseter): the bone node
  // under each column of the belly is pushed out as the muscle contracts,
  // thickening the muscle layer between bone and fascia.
  void add_bellies() {
    m_.bulge_depth.assign(m_.vertex_count, 0.0f);
    m_.bulge_muscle.assign(m_.vertex_count, 0);
    for (std::size_t index = 0; index < kMuscleCount; ++index) {
      const MuscleDefinition& def = facial_muscle_definitions()[index / 2];
      if (def.bulge_mm <= 0.0f) continue;
      const bool left = index % 2 == 0;
      const glm::vec3 origin = point_below(anchor_xy(def.origin, left), 1.0f, 0.0f);
      const glm::vec3 insertion = point_below(anchor_xy(def.insertion, left), 1.0f, 0.0f);
      for (std::uint32_t v = 0; v < m_.vertex_count; ++v) {
        const float w = muscle_belly_weight(rest(node(4, v)), origin, insertion, def.width);
        if (w * def.bulge_mm <= m_.bulge_depth[v] * model::kMillimetresPerUnit) continue;
        m_.bulge_depth[v] = w * def.bulge_mm / model::kMillimetresPerUnit;
        m_.bulge_muscle[v] = static_cast<std::uint8_t>(index);
      }
    }
    for (std::uint32_t v = 0; v < m_.vertex_count; ++v)
      if (m_.jaw_share[v] > 0.0f || m_.bulge_depth[v] > 0.0f)
        m_.moving_bone_columns.push_back(static_cast<std::uint16_t>(v));
  }

  void pin_outline() {
    std::set<std::uint32_t> holes(face_.mouth_slit.begin(), face_.mouth_slit.end());
    for (const auto& eye : face_.eye_holes) holes.insert(eye.begin(), eye.end());
    m_.inverse_mass.assign(m_.moving_node_count, 1.0f / m_.material.node_mass);
    // The nose's tissue is free like the rest: its muscles (the levator
    // labii superioris alaeque nasi and the nasalis) lie in it, between skin
    // and cartilage, and wrinkle and lift it in AU 9. Its columns are thin
    // (the dorsum's 3 mm), held from folding by the skull contact and the
    // prisms' volume.
    for (const auto& loop : model::boundary_loops(face_.skin)) {
      if (holes.contains(loop.front())) continue;
      for (std::uint32_t v : loop)
        for (std::size_t layer = 0; layer < kMovingLayerCount; ++layer) {
          m_.inverse_mass[node(layer, v)] = 0.0f;
          m_.pinned_nodes.push_back(node(layer, v));
        }
    }
  }

  // A face anchor on this face; right-side muscles use the mirrored
  // landmarks and offsets.
  glm::vec2 anchor_xy(const FaceAnchor& anchor, bool left) const {
    const float sx = left ? 1.0f : -1.0f;
    const glm::vec2 offset(anchor.offset.x * sx, anchor.offset.y);
    if (anchor.landmark < 0) return offset;
    auto landmark_xy = [&](int l) {
      const int mirrored = left ? l : model::mirrored_landmark(l);
      const glm::vec3 p = face_.skin.positions[face_.landmark_vertices[static_cast<std::size_t>(mirrored)]];
      return glm::vec2(p.x, p.y);
    };
    glm::vec2 p = landmark_xy(anchor.landmark);
    if (anchor.landmark2 >= 0) p = 0.5f * (p + landmark_xy(anchor.landmark2));
    return p + offset;
  }

  // A point at `xy` below the skin by `share` of the local thickness plus `extra`.
  glm::vec3 point_below(glm::vec2 xy, float share, float extra) const { return point_below_skin(m_, xy, share, extra); }

  void add_muscles() {
    // The nose's columns: every triangle around them is the nose's.
    m_.column_in_nose.assign(m_.vertex_count, 1);
    for (std::size_t f = 0; f < face_.skin.triangles.size(); ++f)
      if (face_.triangle_regions[f] != FaceRegion::nose)
        for (int k = 0; k < 3; ++k) m_.column_in_nose[face_.skin.triangles[f][k]] = 0;
    for (std::size_t index = 0; index < kMuscleCount; ++index) {
      const MuscleDefinition& def = facial_muscle_definitions()[index / 2];
      const bool left = index % 2 == 0;
      const float side = left ? 1.0f : -1.0f;
      TissueMuscle muscle;
      muscle.kind = def.kind;
      muscle.strength = def.strength;
      muscle.jaw_angle_rad = def.jaw_angle_rad;
      muscle.first = muscle.last = static_cast<std::uint32_t>(m_.attach_node.size());
      MuscleAttachments attached{m_.attach_node, m_.attach_weight, m_.attach_column};
      if (def.kind == MuscleKind::sphincter) {
        muscle.origin = point_below(anchor_xy(def.centre, left), 0.0f, 0.0f);
        muscle.pull_scale = def.pull_scale;
        muscle.origin_jaw_share = 0.0f;
        for (std::size_t layer = 1; layer < kMovingLayerCount; ++layer) {
          for (std::uint32_t v = 0; v < m_.vertex_count; ++v) {
            if (!takes_pull(m_, def, v)) continue;
            const std::uint16_t i = node(layer, v);
            const glm::vec3 p = rest(i);
            float w = sphincter_weight(p, muscle.origin, def.semi_axes.x, def.semi_axes.y, def.ring);
            if (p.y > muscle.origin.y) w *= def.upper_share;
            if (def.half) w *= smoothstep((side * (p.x - muscle.origin.x) + 0.04f) / 0.08f);
            w *= attached_layer_share(layer, def.within_the_lips);
            if (w < kLeastAttachment) continue;
            attached.add(i, w, v);
          }
        }
      } else {
        muscle.origin_anchor = anchor_xy(def.origin, left);
        muscle.insertion_anchor = anchor_xy(def.insertion, left);
        const MuscleLine line = lay_muscle_line(m_, def, muscle.origin_anchor, muscle.insertion_anchor);
        muscle.origin = line.origin;
        muscle.origin_jaw_share = def.origin_on_jaw ? 1.0f : 0.0f;
        if (def.kind == MuscleKind::linear) lay_linear_attachments(m_, def, line, nullptr, attached);
      }
      muscle.last = static_cast<std::uint32_t>(m_.attach_node.size());
      m_.muscles.push_back(muscle);
    }
  }

  void copy_basis(const std::array<model::Morph, codec::kAuChannelCount>& basis) {
    const std::size_t n = m_.vertex_count;
    std::vector<float> rows(codec::kAuChannelCount * 3 * n, 0.0f);
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
      const auto& delta = basis[c].vertex_delta;
      for (std::size_t v = 0; v < std::min(n, delta.size()); ++v)
        for (int k = 0; k < 3; ++k) rows[(c * n + v) * 3 + static_cast<std::size_t>(k)] = delta[v][k];
    }
    m_.basis = AuBasis::from_rows(rows, 3 * n);
  }

  void shrink() {
    for (auto* v : {&m_.rest_x, &m_.rest_y, &m_.rest_z, &m_.column_thickness, &m_.jaw_share, &m_.bulge_depth, &m_.inverse_mass,
                    &m_.spring_rest, &m_.element_rest_volume, &m_.element_force_scale, &m_.skin_rest_area,
                    &m_.attach_weight})
      v->shrink_to_fit();
    m_.column_on_bone.shrink_to_fit();
    m_.column_in_nose.shrink_to_fit();
    m_.bulge_muscle.shrink_to_fit();
    for (auto* v : {&m_.moving_bone_columns, &m_.pinned_nodes, &m_.spring_a, &m_.spring_b, &m_.attach_node, &m_.attach_column})
      v->shrink_to_fit();
    m_.skull_normal.shrink_to_fit();
    m_.spring_kind.shrink_to_fit();
    for (auto& corner : m_.element_node) corner.shrink_to_fit();
    m_.skin_triangles.shrink_to_fit();
    m_.muscles.shrink_to_fit();
  }

  // Gershgorin: the largest eigenvalue of the stiffness matrix is at most
  // twice the largest sum of the (stiff-branch) slopes meeting at one node;
  // the semi-implicit Euler step is stable below 2 / omega_max, of which we
  // keep 1.8 for the dampers and the volume forces. The 60-second
  // full-activation tests hold this to account.
  void estimate_stable_substep() {
    std::vector<float> sum(m_.node_count, 0.0f);
    for (std::size_t s = 0; s < m_.spring_count(); ++s) {
      const StressStrainCurve& c = m_.material.curves[static_cast<std::size_t>(m_.spring_kind[s])];
      const float k = c.stiffness * c.stiff_ratio;
      sum[m_.spring_a[s]] += k;
      sum[m_.spring_b[s]] += k;
    }
    // The volume force's row sum: kappa s |g_i| sum_j |g_j| at the bulk
    // curve's stiffer slope (halved: the springs' sums are doubled below).
    for (std::size_t e = 0; e < m_.element_count(); ++e) {
      PrismNodes p, gradient;
      const auto nodes = m_.element(e);
      for (std::size_t k = 0; k < 6; ++k) p[k] = rest(nodes[k]);
      prism_volume(p, &gradient);
      float total = 0.0f;
      for (const glm::vec3& g : gradient) total += glm::length(g);
      for (std::size_t k = 0; k < 6; ++k)
        sum[nodes[k]] +=
            0.5f * m_.material.volume_stiffness * std::max(m_.material.volume_stiff_ratio, 1.0f) *
            m_.element_force_scale[e] * glm::length(gradient[k]) * total;
    }
    // The true bound of the plain masses: no node is made heavier to buy a
    // longer sub-step (mass scaling would change the dynamics the face shows
    // and hide a too-stiff material), so the solver takes as many sub-steps
    // as the stiffest node needs.
    float worst = 0.0f;
    for (std::size_t i = 0; i < m_.moving_node_count; ++i)
      if (m_.inverse_mass[i] != 0.0f) worst = std::max(worst, sum[i] * m_.inverse_mass[i]);
    m_.stable_substep_s = 1.8f / std::sqrt(2.0f * worst);
  }

  const model::GenericFace& face_;
  TissueModel& m_;
  std::vector<EdgeInfo> edges_;
};

}  // namespace

TissueMaterial TissueMaterial::normal() {
  TissueMaterial m;
  auto set = [&](SpringKind kind, float stiffness, float knee, float damping) {
    m.curves[static_cast<std::size_t>(kind)] = {stiffness, 2.0f, knee, 0.0f};
    m.damping[static_cast<std::size_t>(kind)] = damping;
  };
  // Slopes chosen so that the tissue over the bone has its slowest modes
  // near 5 Hz (expressions take 50-300 ms to appear) and the fastest below
  // what seven explicit sub-steps per 30 Hz frame integrate stably (1/188 s
  // on the generic face, the plain masses' Gershgorin bound).
  set(SpringKind::epidermis, 375.0f, 0.15f, 1.0f);
  set(SpringKind::dermis, 300.0f, 0.15f, 1.0f);
  set(SpringKind::fat, 100.0f, 0.3f, 1.0f);
  set(SpringKind::fascia, 300.0f, 0.2f, 1.0f);
  set(SpringKind::column_skin, 750.0f, 0.2f, 1.0f);
  set(SpringKind::column_muscle, 1500.0f, 0.4f, 1.0f);
  set(SpringKind::shear_skin, 300.0f, 0.2f, 1.0f);
  set(SpringKind::shear_muscle, 700.0f, 0.4f, 1.0f);
  set(SpringKind::bending, 40.0f, 0.2f, 0.5f);
  m.volume_stiffness = 1500.0f;
  // Every prism within 5 % of its volume under a single unit would need a
  // nearly incompressible tissue (soft tissue is: Fung 1993, "Biomechanics:
  // Mechanical Properties of Living Tissues"), but a bulk slope three times
  // this one everywhere costs the units their travel (AU 25 0.85, AU 17
  // 0.88 of it), as the lid and chin columns cannot shear without giving
  // volume. The bulk curve (bulk_curve.hpp) stiffens a prism only past a
  // knee: at 1.5 times past 4 % the worst prism under a single unit is
  // 49 % instead of 56 %, at twice 44 %, three times 36 %. It is on at
  // 1.5. Before the projective solver had its bond to the bone it was off:
  // the face then rested on a held joy for 37 of 180 room ticks instead of
  // 70-77 (tissue awake is the rooms' cost), and the corrective basis cut
  // the held-out error only to 0.498 instead of 0.492, against its bound
  // of a half. With the bond, at 1.5, a held joy rests 81 of 180 ticks
  // (132 linear) and the basis cuts to 0.494 (0.488 linear); at 2 the cut
  // is 0.498, at the bound (README, "The volume requirement"). (All at one
  // projective step a frame; at two a held joy rests all 180 ticks and
  // the basis cuts to 0.453.)
  m.volume_knee = 0.04f;
  m.volume_stiff_ratio = 1.5f;
  // Damps the 5 Hz modes at about half of critical (30 / (2 x 2 pi 5)), so
  // an expression settles without ringing; on relative speeds, so it takes
  // nothing from tissue that moves with its bone.
  m.bone_damping = 30.0f;
  m.node_mass = 1.0f;
  // Lying down moves the lower face's skin 1.17 mm cranially (Hernandez et
  // al. 2022, 175 adults, 3D surface scans upright and supine): this scale
  // gives 1.18 mm on the generic face (tests/physics head_loads_test.cpp).
  m.load_scale = 0.0141f;
  return m;
}

TissueMaterial TissueMaterial::loose() {
  TissueMaterial m = normal();
  // Every skin layer softer (the elastin and collagen lost with age); the
  // epidermis and dermis also longer than the neutral face and tension only
  // (the paper's "epidermal/dermal stress-strain curves", Fig. 2b): slack at
  // rest, not pre-compressed. The layers under them keep their natural
  // length and resist compression, so a face let go comes back.
  for (SpringKind kind : {SpringKind::epidermis, SpringKind::dermis, SpringKind::fat, SpringKind::column_skin,
                          SpringKind::shear_skin, SpringKind::bending})
    m.curves[static_cast<std::size_t>(kind)].stiffness *= 0.5f;
  for (SpringKind kind : {SpringKind::epidermis, SpringKind::dermis}) {
    StressStrainCurve& c = m.curves[static_cast<std::size_t>(kind)];
    c.residual_strain = -0.05f;
    c.compression_share = 0.0f;
  }
  return m;
}

std::size_t TissueModel::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return sizeof(*this) + bytes(rest_x) + bytes(rest_y) + bytes(rest_z) + bytes(skull_normal) +
         bytes(column_thickness) + bytes(column_on_bone) + bytes(jaw_share) + bytes(bulge_depth) + bytes(bulge_muscle) + bytes(moving_bone_columns) + bytes(inverse_mass) + bytes(pinned_nodes) + bytes(spring_a) + bytes(spring_b) +
         bytes(spring_rest) + bytes(spring_kind) + 6 * bytes(element_node[0]) + bytes(element_rest_volume) +
         bytes(element_force_scale) + bytes(skin_triangles) + bytes(skin_rest_area) + bytes(muscles) +
         bytes(attach_node) + bytes(attach_weight) + bytes(attach_column) + bytes(column_in_nose) +
         muscle_particles.memory_bytes() +
         basis.memory_bytes();
}

std::shared_ptr<const TissueModel> build_tissue_model(
    const model::GenericFace& face, const std::array<model::Morph, codec::kAuChannelCount>& basis,
    const TissueOptions& options) {
  assert(face.skin.positions.size() * kTissueLayerCount < 65536 && "node indices are 16-bit");
  auto m = std::make_shared<TissueModel>();
  Builder(face, options, *m).build(basis);
  m->muscle_particles = build_muscle_particles(*m);
  return m;
}

}  // namespace fw::physics
