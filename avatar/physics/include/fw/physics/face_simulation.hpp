#pragma once
// One avatar's physics face: the tissue model's state, one array per
// quantity, stepped by a mass-spring, an XPBD or a projective-dynamics solver.
// The server composes behavior and physics per avatar per tick:
//
//   FaceSimulation sim(face, {.solver = Solver::mass_spring, .seed = 7});
//   sim.set_action_units(targets);     // FACS intensities -> muscle activations
//   if (!sim.at_rest()) sim.step(1.0 / 30);
//   FaceMeasurement m = sim.measure(); // the surface projected onto the AU basis
//
// Time is passed in; there are no globals; the same options, seed and calls
// give the same result. Not thread-safe: one caller at a time (FacePool steps
// many faces in parallel, each on one thread).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/corrective_projection.hpp"
#include "fw/physics/facial_muscles.hpp"
#include "fw/physics/head_loads.hpp"
#include "fw/physics/muscle_course.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics {

enum class Solver : std::uint8_t {
  mass_spring,  ///< viscoelastic units, muscle forces, semi-implicit Euler sub-steps (Lee et al. 1995)
  pbd,          ///< XPBD: compliant distance, volume and muscle-tie constraints (Macklin et al. 2016; the PBD face paper)
  projective,   ///< projective dynamics, implicit, one factored matrix per model (Bouaziz et al. 2014)
};

class ProjectiveStepper;

struct SimulationOptions {
  Solver solver = Solver::mass_spring;
  std::uint64_t seed = 1;
  /// How far each face's muscle strengths depart from the table, drawn from
  /// the seed (muscle_strength_factors, muscle_variation.hpp: real faces
  /// differ): 1 a person's spread, 0 the reference face.
  float individual_variation = 0.0f;
  /// How far each face's muscle courses depart from the table, drawn from
  /// the seed (muscle_course_shifts, laid by muscle_course.hpp): 1 a
  /// typical person, 0 the reference face; clamped to [0, 1].
  float course_variation = 0.0f;
  /// Longest sub-step, seconds; a mass-spring step never exceeds the
  /// model's stable bound either. 1/120 s is the paper's four per frame.
  /// XPBD takes xpbd_substep_s instead; the projective solver steps up to
  /// 17.5 ms whatever this says (ProjectiveStepper::kLongestStepS).
  double max_substep_s = 1.0 / 120.0;
  /// Muscle excitation-contraction lag: first-order time constants, seconds
  /// (Winters 1995; Thelen 2003, "Adjustment of muscle mechanics model
  /// parameters to simulate dynamic contractions in older adults", J.
  /// Biomech. Eng. 125: 15 ms up, 50 ms down, fitted on limb muscles).
  /// Calcium is released faster than it is taken back, so a muscle relaxes
  /// slower than it contracts. The mimetic muscles are at least as fast as
  /// those limb muscles: most hold 15-38 % slow (type I) fibres, where the
  /// gracilis holds 36 % and the rectus femoris 48 % (Happak, Burggasser,
  /// Liu, Gruber & Freilinger 1988, "Histochemical characteristics of human
  /// mimic muscles", J. Neurol. Sci. 83), the orbicularis oris 29 % (Stal,
  /// Eriksson, Eriksson & Thornell 1990, Arch. Oral Biol. 35); only the
  /// frontalis and buccinator are slower (53-77 %).
  float activation_time_s = 0.015f;
  float deactivation_time_s = 0.05f;
  /// An extra acceleration pulling the tissue down (-y), model units per
  /// s^2, on top of what the head's pose and motion put on it
  /// (set_head_pose): for tests and the paper's sag figure. 0: the neutral
  /// mesh is the shape balanced under gravity with the head upright.
  float gravity = 0.0f;
  /// Longest XPBD sub-step, seconds: two per 30 Hz frame. XPBD is stable at
  /// any step and its material does not depend on it (xpbd_test.cpp).
  double xpbd_substep_s = 1.0 / 60.0;
  /// Constraint passes per XPBD sub-step: XPBD's material does not depend
  /// on them once converged; three bring the settled shapes of 2 and 8
  /// sub-steps per frame within 2 % of their travel (xpbd_test.cpp).
  int pbd_iterations = 3;
};

/// The simulated surface as FaceParams' action-unit and corrective parts.
struct FaceMeasurement {
  std::array<float, codec::kAuChannelCount> action_units{};  ///< least squares, each in [0,1]
  float residual_rms_mm = 0;  ///< RMS over the skin vertices of what the AUs do not explain
  /// What the AUs leave, projected on the face's corrective components
  /// (least squares, each in [-1,1]); 0 where the face has none.
  std::array<float, codec::kCorrectiveCount> corrective{};
};

class FaceSimulation {
 public:
  /// A simulation of `face` measured against its own action units and
  /// corrective components.
  explicit FaceSimulation(const model::GenericFace& face, const SimulationOptions& options = {});
  /// A simulation of an avatar's fitted face, measured against its cloned
  /// morphs and corrective components.
  explicit FaceSimulation(const model::AvatarModel& avatar, const SimulationOptions& options = {});
  /// A simulation sharing a tissue model with others (faces of one avatar
  /// model), and the corrective components made for that model's AU basis
  /// (none: the measurement's corrective weights stay 0).
  explicit FaceSimulation(std::shared_ptr<const TissueModel> model, const SimulationOptions& options = {},
                          std::shared_ptr<const CorrectiveBasis> correctives = nullptr);

  /// New AU intensity targets (kAuChannels order; clamped to [0,1], NaN = 0),
  /// turned into muscle activations by au_muscle_map.hpp. Wakes a resting face
  /// if they differ from the last ones.
  void set_action_units(const std::array<float, codec::kAuChannelCount>& targets);
  /// Drives the muscles directly (each clamped to [0,1]), bypassing the AU table.
  void set_muscle_activations(const std::array<float, kMuscleCount>& targets);
  /// The head's pose at the end of the next step (head_loads.hpp): its
  /// turn away from upright and its motion load the tissue, which sags and
  /// lags. The tissue takes the load when it moves by more than the skin
  /// would show (face_simulation.cpp's kRestLoad): a swaying head lets its
  /// face rest, a turning or tilting one wakes it.
  void set_head_pose(const HeadPose& pose);

  // The face lab's physics level (face_simulation_lab.cpp).
  /// The least activation of each muscle (each clamped to [0,1], NaN = 0):
  /// a muscle is driven by the larger of this and what the AU targets give
  /// it, from now on and by every later set_action_units. All 0: the AU
  /// table alone again. Wakes a resting face if its targets change.
  void set_muscle_floor(const std::array<float, kMuscleCount>& floor);
  const std::array<float, kMuscleCount>& muscle_floor() const { return floor_; }
  /// The same face with another tissue model: another material (the
  /// skin's age and looseness, TissueMaterial::aged), or the avatar's own
  /// fitted face once it is built (avatar_tissue.hpp). `model` must have
  /// the same node count. Every node keeps its displacement from the rest
  /// shape and its speed, so the face goes on from where it is (no jump in
  /// what measure() sees), and it wakes. The muscles keep this face's
  /// variation, on the new model's strengths and landmarks.
  void replace_model(std::shared_ptr<const TissueModel> model);
  /// The corrective components measure() projects on from now on (null:
  /// none), built against the AU basis of the model the face now has.
  void set_correctives(std::shared_ptr<const CorrectiveBasis> correctives) { correctives_ = std::move(correctives); }

  /// Advances by `dt_seconds` (one rendered frame; internally several
  /// sub-steps). dt is clamped to [0, 1] s; a non-finite dt is ignored. A face
  /// at rest only advances its clock.
  void step(double dt_seconds);

  /// True when nothing moves, the muscles and the jaw have reached their
  /// targets and the targets have not changed: stepping would change nothing.
  bool at_rest() const { return at_rest_; }

  /// Projects the current surface onto the AU basis (least squares with the
  /// weights kept in [0,1], warm-started from the last measurement), and
  /// what those leave onto the corrective components (corrective_projection.hpp).
  FaceMeasurement measure();

  // Inspection, for tests, tools and benchmarks.
  const TissueModel& model() const { return *model_; }
  const SimulationOptions& options() const { return options_; }
  double time_s() const { return time_s_; }
  glm::vec3 node_position(std::size_t node) const { return {x_[node], y_[node], z_[node]}; }
  /// The skin vertices (epidermis nodes), model units.
  std::vector<glm::vec3> surface() const;
  float jaw_angle_rad() const { return jaw_angle_; }
  /// The acceleration field on the tissue over the last step (the head's
  /// load, scaled, plus SimulationOptions::gravity).
  const HeadLoad& load() const { return load_; }
  const std::array<float, kMuscleCount>& muscle_activations() const { return activation_; }
  /// Sum of 1/2 m v^2 over the moving nodes.
  double kinetic_energy() const;
  /// Volume of element `e` now, cubic model units.
  float element_volume(std::size_t e) const;
  /// Height of moving node `node` above the skull plane under it, model units.
  float height_above_skull(std::size_t node) const;
  /// Sub-steps that step(dt) takes.
  int substeps_for(double dt_seconds) const;
  /// Bytes of state this simulation owns (the shared model not counted).
  std::size_t state_bytes() const;

 private:
  friend class ProjectiveStepper;  // steps faces of one model together (projective_dynamics.hpp)
  /// Advances the clock; the sub-steps step(dt) takes, 0 if the face does not move.
  int begin_step(double& dt_seconds);
  void update_rest_state();
  /// strength_ and course_ from the model and this face's seed and variation.
  void lay_muscles();
  std::array<glm::vec3, kMuscleCount> muscle_origins() const;
  void substep(float h);
  void update_muscles_and_jaw(float h);
  void place_bone(float h);
  void move_node_with_jaw(std::size_t i, float share, float h, const glm::vec3& normal, float lift);
  void mass_spring_substep(float h);
  void pbd_substep(float h, const std::array<float, kMuscleCount>& activation);  // XPBD (xpbd_step.cpp)
  void resolve_skull();
  void resolve_lips();
  /// The contacts after a step: the skull, then the lips.
  void resolve_contacts() { resolve_skull(), resolve_lips(); }
  glm::vec3 jaw_turned(const glm::vec3& p, float share) const;

  std::shared_ptr<const TissueModel> model_;
  std::shared_ptr<const CorrectiveBasis> correctives_;  ///< null: no corrective weights
  SimulationOptions options_;

  std::array<float, kMuscleCount> strength_factor_{};  ///< muscle_strength_factors
  std::array<float, kMuscleCount> strength_{};
  /// This face's muscle courses on the model (the seed's, muscle_course.hpp):
  /// what every solver reads for the muscles' origins and attachment weights.
  MuscleCourse course_;
  std::array<float, kMuscleCount> target_{}, activation_{};
  std::array<float, codec::kAuChannelCount> au_targets_{};
  std::array<float, kMuscleCount> floor_{};  ///< set_muscle_floor
  float jaw_angle_ = 0, jaw_speed_ = 0, jaw_target_ = 0;
  float jaw_cos_ = 1, jaw_sin_ = 0;
  HeadMotion head_;
  HeadLoad load_;  ///< over this step: the head's, plus options_.gravity
  glm::vec3 jaw_glide_{0.0f};  ///< the condyles' glide down the eminence now (TissueModel::jaw_glide)
  double time_s_ = 0;
  bool at_rest_ = true;
  float max_speed2_ = 0;
  // One array per quantity, #nodes each (bone nodes included, so springs
  // index them directly); f doubles as the previous positions in XPBD.
  std::vector<float> x_, y_, z_, vx_, vy_, vz_, fx_, fy_, fz_;
  std::vector<glm::vec3> skull_normal_;  ///< #V, turned with the jaw
  std::array<float, codec::kAuChannelCount> last_weights_{};
};

}  // namespace fw::physics
