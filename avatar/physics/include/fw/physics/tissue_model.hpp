#pragma once
// The layered soft-tissue lattice of one face, built once from its mesh and
// shared (read-only) by every simulation of that face. Lee, Terzopoulos &
// Waters 1995, as used by the behavioral-animation paper (sec. 2-3.1): the
// skin mesh is extruded inward into five node layers (epidermis, dermis,
// subcutaneous fat, fascia, bone), each skin triangle becomes a column of
// four triangular prism elements, and the nodes are joined by viscoelastic
// units: the triangle edges in every layer, the columns between layers and
// two crossing diagonals on every prism side. The bone layer is fixed to the
// skull, its lower part to the mandible, which turns about its hinge and
// glides forward as it opens wide; over the masseter's belly it rises as the
// muscle contracts.
//
// Storage is one array per quantity (structure of arrays, 16-bit node
// indices), so a simulation step is a few linear passes the compiler can
// vectorise and one model fits in a core's cache.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/au_projection.hpp"
#include "fw/physics/facial_muscles.hpp"
#include "fw/physics/muscle_particles.hpp"
#include "fw/physics/projective_system_cache.hpp"
#include "fw/physics/stress_strain.hpp"

namespace fw::physics {

/// Node layers, outside in. Node (layer, v) has index layer * #V + v, so the
/// epidermis nodes are the skin vertices and the moving nodes come first.
enum class TissueLayer : std::uint8_t { epidermis, dermis, fat, fascia, bone };
inline constexpr std::size_t kTissueLayerCount = 5;
inline constexpr std::size_t kMovingLayerCount = 4;  ///< all but the bone

/// Kinds of viscoelastic unit; each kind has its own curve and damping.
enum class SpringKind : std::uint8_t {
  epidermis, dermis, fat, fascia,  ///< triangle edges within a layer
  column_skin,                     ///< between the skin layers of one column
  column_muscle,                   ///< fascia to bone (through the muscle layer)
  shear_skin, shear_muscle,        ///< prism side diagonals
  bending,                         ///< epidermis, across each inner edge (PBD paper sec. 5.9)
  count
};
inline constexpr std::size_t kSpringKindCount = static_cast<std::size_t>(SpringKind::count);

/// The biomechanical parameters. Force unit: the pull that accelerates one
/// node mass by one model unit per second squared.
struct TissueMaterial {
  std::array<StressStrainCurve, kSpringKindCount> curves{};
  std::array<float, kSpringKindCount> damping{};  ///< force per unit of stretching speed
  float volume_stiffness = 0;   ///< force per model unit of thickness lost or gained
  /// The bulk curve's knee: past this share of its rest volume lost or
  /// gained, a prism's slope is volume_stiff_ratio x volume_stiffness
  /// (bulk_curve.hpp). 0 with a ratio of 1: linear.
  float volume_knee = 0;
  float volume_stiff_ratio = 1;  ///< >= 1
  /// 1/s per node mass: each moving node's viscous bond to the bone of its
  /// column, on their relative speed (the mass-spring solver's damping
  /// beside the units' own; not a drag of the world frame).
  float bone_damping = 0;
  float node_mass = 1;
  /// The share of a real acceleration (gravity off upright, a turning head)
  /// that loads the lattice. Its node mass is a numerical one, chosen with
  /// the slopes for how fast expressions develop; the tissue's real weight
  /// against those slopes is measured: this scale makes lying down (gravity
  /// from the back of the head instead of from above) move the lower face's
  /// skin as far as it moves in people (tissue_model.cpp).
  float load_scale = 0;
  /// Normal adult skin (the paper's Fig. 2a).
  static TissueMaterial normal();
  /// Looser, aged skin (Fig. 2b, "the epidermal/dermal stress-strain
  /// curves"): every skin layer softer, and the epidermis and dermis with a
  /// negative residual strain and tension only, so the skin hangs slack at
  /// its neutral length instead of pushing. The fat, the columns, the shears
  /// and the bending unit keep their natural length and compression: made
  /// slack too, nothing brought a released face back (2.5 mm off its rest
  /// 2.5 s after a smile let go).
  static TissueMaterial loose();
  /// Between the two, for the face lab (aged_skin.cpp): `age` (0 .. 1)
  /// softens the skin layers' slopes from normal() to loose()'s half (the
  /// elastin lost with age), `looseness` (0 .. 1) takes the epidermis' and
  /// dermis' residual strain from 0 to loose()'s -0.05 and their compression
  /// share from 1 to 0 (skin slack at its neutral length).
  /// aged(0, 0) is normal(), aged(1, 1) is loose(); values are clamped.
  static TissueMaterial aged(float age, float looseness);
};

/// One muscle as laid on this face.
struct TissueMuscle {
  MuscleKind kind = MuscleKind::linear;
  float strength = 0;
  glm::vec3 origin{0.0f};       ///< rest position; linear: the bony origin, sphincter: the centre
  float origin_jaw_share = 0;   ///< how much of the jaw's turn the origin follows
  glm::vec3 pull_scale{1.0f};   ///< sphincters: per-axis weight of the pull toward the centre
  float jaw_angle_rad = 0;      ///< jaw angle held at activation 1
  /// Linear and jaw muscles: the face-plane anchors the origin and the
  /// insertion are laid under (a person's course moves them, muscle_course.hpp).
  glm::vec2 origin_anchor{0.0f}, insertion_anchor{0.0f};
  std::uint32_t first = 0, last = 0;  ///< its attachments: [first, last)
};

struct TissueModel {
  std::uint32_t vertex_count = 0;      ///< #V: skin vertices, nodes per layer
  std::uint32_t node_count = 0;        ///< #V x 5
  std::uint32_t moving_node_count = 0; ///< #V x 4 (the bone layer is kinematic)

  std::vector<float> rest_x, rest_y, rest_z;  ///< #nodes, model units
  std::vector<glm::vec3> skull_normal;        ///< #V, unit, out of the bone, at rest
  /// #V, model units, skin to bone: the region's depth
  /// (regional_thickness.hpp), thinner where columns converge.
  std::vector<float> column_thickness;
  /// #V: 1 where the tissue is tied to the bone under it; 0 under the lips
  /// and mouth corners, which only slide over the teeth.
  std::vector<std::uint8_t> column_on_bone;
  /// The lips' contacts (lip_contact.hpp): opposite skin vertices on the
  /// inner edges of the lips, upper then lower.
  std::vector<std::array<std::uint16_t, 2>> lip_pairs;
  std::array<float, kTissueLayerCount> layer_depth{};       ///< share of the thickness at each layer
  std::array<float, kTissueLayerCount> layer_min_height{};  ///< share of the thickness a node keeps above the skull

  // The articulated jaw: bone nodes follow its turn about the hinge (an axis
  // along x) by their column's share, the lower lip fully, the upper not.
  // Past jaw_glide_onset_rad the condyles also glide forward and down the
  // articular eminence, in proportion to the opening, by jaw_glide at
  // jaw_max_rad: rotation first, then rotation and translation.
  glm::vec3 jaw_hinge{0.0f};
  glm::vec3 jaw_glide{0.0f};                  ///< model units, at jaw_max_rad
  float jaw_glide_onset_rad = 0;
  std::vector<float> jaw_share;               ///< #V
  float jaw_min_rad = -0.03f, jaw_max_rad = 0.45f;
  /// A bulging muscle's belly under the fascia (the masseter's): per column,
  /// how far its bone node is pushed out along the skull normal at the
  /// muscle's activation 1 (model units, 0: no belly) and which muscle.
  std::vector<float> bulge_depth;             ///< #V
  std::vector<std::uint8_t> bulge_muscle;     ///< #V, a muscle index
  /// Columns whose bone node moves: a jaw share > 0 or a belly under it.
  std::vector<std::uint16_t> moving_bone_columns;

  /// Per moving node: 1 / mass, or 0 for the columns on the mesh's outer
  /// boundary, where the face's tissue goes on into scalp and neck: they are
  /// held to the bone (and the jaw) instead of left as a free edge.
  std::vector<float> inverse_mass;
  std::vector<std::uint16_t> pinned_nodes;

  std::vector<std::uint16_t> spring_a, spring_b;  ///< node indices
  std::vector<float> spring_rest;                 ///< rest length, model units
  std::vector<SpringKind> spring_kind;
  TissueMaterial material;

  /// Node k of every element, k = 0..2 the outer triangle, 3..5 the inner
  /// one (one array per corner, so a block of elements loads contiguously).
  std::array<std::vector<std::uint16_t>, 6> element_node;
  std::vector<float> element_rest_volume;                   ///< cubic model units
  /// 1 / (outer rest area x mean |dV/dp| at rest): turns a volume change
  /// into the change of the element's thickness and its gradient into unit
  /// directions, so volume_stiffness is a slope like the springs', whatever
  /// the layer's thickness.
  std::vector<float> element_force_scale;

  std::vector<glm::uvec3> skin_triangles;     ///< epidermis triangles (PBD area constraints)
  std::vector<float> skin_rest_area;

  std::vector<TissueMuscle> muscles;          ///< kMuscleCount, facial_muscles.hpp order
  std::vector<std::uint16_t> attach_node;
  std::vector<float> attach_weight;
  std::vector<std::uint16_t> attach_column;   ///< the attached node's column (skin vertex)
  /// #V: 1 for the nose's columns, which only the nose's own muscles pull
  /// (MuscleDefinition::moves_nose).
  std::vector<std::uint8_t> column_in_nose;
  /// The muscles as particles along their action lines, for the XPBD solver.
  MuscleParticles muscle_particles;

  /// The AU basis the surface is measured against: kAuChannelCount rows of
  /// 3 #V values (x, y, z per vertex), model units at intensity 1.
  AuBasis basis;

  /// Longest explicit sub-step that the stiffest node allows (a Gershgorin
  /// bound on the stiffness matrix over the plain masses), seconds.
  float stable_substep_s = 0;

  /// The projective-dynamics solver's factorisations, made when a face of
  /// this model first steps with it (projective_system_cache.hpp).
  ProjectiveSystemCache projective_systems;
  /// A model of the same topology and material (the generic face's) whose
  /// projective-dynamics weights and factorisations this one shares, keeping
  /// its own rest shape (avatar_tissue.hpp); null: its own.
  std::shared_ptr<const TissueModel> projective_reference;

  std::size_t spring_count() const { return spring_a.size(); }
  std::size_t element_count() const { return element_node[0].size(); }
  std::array<std::uint16_t, 6> element(std::size_t e) const {
    return {element_node[0][e], element_node[1][e], element_node[2][e],
            element_node[3][e], element_node[4][e], element_node[5][e]};
  }
  /// Bytes held by this model.
  std::size_t memory_bytes() const;
};

struct TissueOptions {
  TissueMaterial material = TissueMaterial::normal();
};

/// Builds the tissue model of `face`, measuring against `basis`.
/// @param[in] face     a sound face (generic or fitted), < 13,000 skin vertices
/// @param[in] basis    one morph per AU channel, #V vertex deltas each
/// @param[in] options  material
std::shared_ptr<const TissueModel> build_tissue_model(
    const model::GenericFace& face, const std::array<model::Morph, codec::kAuChannelCount>& basis,
    const TissueOptions& options = {});

}  // namespace fw::physics
