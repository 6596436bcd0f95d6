#include "fw/physics/face_simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/model/landmark_template.hpp"
#include "fw/physics/au_muscle_map.hpp"
#include "fw/physics/au_projection.hpp"
#include "fw/physics/lip_contact.hpp"
#include "fw/physics/muscle_activation.hpp"
#include "fw/physics/muscle_variation.hpp"
#include "fw/physics/prism_volume.hpp"
#include "fw/physics/skull_contact.hpp"
#include "projective_dynamics.hpp"

namespace fw::physics {
namespace {

// Thresholds under which a face counts as at rest: the skin moves slower
// than 0.006 mm/s and every muscle is within 0.01 % of its target.
constexpr float kRestSpeed = 1e-4f;
constexpr float kRestActivation = 1e-4f;
// The tissue takes a new load from its head only when it differs from the
// one it has by more than kRestLoad: the skin settles about 0.5 mm (RMS)
// further per model unit per s^2 of load, so 0.25 is 0.12 mm, a quarter of
// what a viewer could notice. Heads sway a little all the time
// (eye_head.cpp's noise: 2 degrees of pitch and 1.5 of roll move the load by
// up to 0.19); a load that followed every sway would keep the tissue
// creeping and every face awake. A tilt of more than 6 degrees is followed.
constexpr float kRestLoad = 0.25f;
// A turn's own load (its speeding up and its centripetal pull) is taken
// only from this size on (0.5 mm settled): a gaze shift's turn (up to 30
// rad/s^2 in the rooms' behaviour, 0.85 here) moves the skin by under 0.2
// mm for a tenth of a second and would wake every face at every glance; a
// shake of the head (some hundred rad/s^2) is shown.
constexpr float kVisibleTurnLoad = 1.0f;

// The size of a turn's load: its linear part at the face's 2-unit reach
// from the neck pivot.
float turn_load(const glm::mat3& linear) {
  float size = 0.0f;
  for (int c = 0; c < 3; ++c) size = std::max(size, glm::length(linear[c]));
  return 2.0f * size;
}

// How far apart two loads are, units/s^2: the uniform parts', plus the
// linear parts' at the face's 2-unit reach from the neck pivot.
float load_gap(const HeadLoad& a, const HeadLoad& b) {
  return glm::length(a.uniform - b.uniform) + turn_load(a.linear - b.linear);
}
constexpr double kMaxStepS = 1.0;
// The jaw: a critically damped turn toward the angle its muscles hold.
constexpr float kJawOmega = 20.0f;

}  // namespace

FaceSimulation::FaceSimulation(const model::GenericFace& face, const SimulationOptions& options)
    : FaceSimulation(build_tissue_model(face, face.action_units), options) {
  correctives_ = std::make_shared<const CorrectiveBasis>(CorrectiveBasis::from_morphs(face.correctives, model_->basis));
}

FaceSimulation::FaceSimulation(const model::AvatarModel& avatar, const SimulationOptions& options)
    : FaceSimulation(build_tissue_model(avatar.face, avatar.morphs), options) {
  correctives_ = std::make_shared<const CorrectiveBasis>(CorrectiveBasis::from_morphs(avatar.correctives, model_->basis));
}

FaceSimulation::FaceSimulation(std::shared_ptr<const TissueModel> model, const SimulationOptions& options,
                               std::shared_ptr<const CorrectiveBasis> correctives)
    : model_(std::move(model)), correctives_(std::move(correctives)), options_(options) {
  assert(model_);
  const TissueModel& m = *model_;
  x_ = m.rest_x;
  y_ = m.rest_y;
  z_ = m.rest_z;
  for (auto* v : {&vx_, &vy_, &vz_, &fx_, &fy_, &fz_}) v->assign(m.node_count, 0.0f);
  skull_normal_ = m.skull_normal;
  // The neutral mesh is the shape at rest with the head upright; an extra
  // pull gives the tissue somewhere to go.
  load_.uniform.y = -options_.gravity;
  at_rest_ = options_.gravity == 0.0f;
  strength_factor_ = muscle_strength_factors(options_.seed, options_.individual_variation);
  lay_muscles();
}

void FaceSimulation::lay_muscles() {
  const TissueModel& m = *model_;
  for (std::size_t i = 0; i < kMuscleCount; ++i) strength_[i] = m.muscles[i].strength * strength_factor_[i];
  course_ = lay_muscle_course(m, muscle_course_shifts(options_.seed, options_.course_variation),
                              options_.solver == Solver::pbd);
}

void FaceSimulation::set_action_units(const std::array<float, codec::kAuChannelCount>& targets) {
  au_targets_ = targets;
  std::array<float, kMuscleCount> activations = physics::muscle_activations(targets);
  for (std::size_t i = 0; i < kMuscleCount; ++i) activations[i] = std::max(activations[i], floor_[i]);
  set_muscle_activations(activations);
}

void FaceSimulation::set_muscle_activations(const std::array<float, kMuscleCount>& targets) {
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    const float t = std::isfinite(targets[i]) ? std::clamp(targets[i], 0.0f, 1.0f) : 0.0f;
    if (t != target_[i]) at_rest_ = false;
    target_[i] = t;
  }
  float jaw = 0.0f;
  for (std::size_t i = 0; i < kMuscleCount; ++i) jaw += 0.5f * target_[i] * model_->muscles[i].jaw_angle_rad;
  jaw_target_ = std::clamp(jaw, model_->jaw_min_rad, model_->jaw_max_rad);
}

int FaceSimulation::substeps_for(double dt_seconds) const {
  double h = options_.max_substep_s > 0.0 ? options_.max_substep_s : 1.0 / 120.0;
  if (options_.solver == Solver::mass_spring) h = std::min(h, double(model_->stable_substep_s));
  if (options_.solver == Solver::pbd) h = options_.xpbd_substep_s > 0.0 ? options_.xpbd_substep_s : 1.0 / 60.0;
  if (options_.solver == Solver::projective) h = ProjectiveStepper::kLongestStepS;
  return std::max(1, static_cast<int>(std::ceil(std::clamp(dt_seconds, 0.0, kMaxStepS) / h - 1e-9)));
}

void FaceSimulation::set_head_pose(const HeadPose& pose) { head_.set_pose(pose); }

int FaceSimulation::begin_step(double& dt_seconds) {
  if (!std::isfinite(dt_seconds) || dt_seconds <= 0.0) return 0;
  dt_seconds = std::min(dt_seconds, kMaxStepS);
  time_s_ += dt_seconds;
  // Every frame, at rest or not, so that the head's speed is always that
  // of its last frame.
  HeadLoad load = head_.advance(dt_seconds, model_->material.load_scale);
  load.uniform.y -= options_.gravity;
  if (turn_load(load.linear) < kVisibleTurnLoad) load.linear = glm::mat3(0.0f);
  // A turn that ends lets go at once, so that its pull does not linger.
  const bool turn_ended = load.linear == glm::mat3(0.0f) && load_.linear != glm::mat3(0.0f);
  if (turn_ended || load_gap(load, load_) > kRestLoad) {
    at_rest_ = false;
    load_ = load;
  }
  return at_rest_ ? 0 : substeps_for(dt_seconds);
}

void FaceSimulation::step(double dt_seconds) {
  const int n = begin_step(dt_seconds);
  if (n == 0) return;
  const float h = static_cast<float>(dt_seconds / n);
  for (int i = 0; i < n; ++i) substep(h);
  update_rest_state();
}

void FaceSimulation::update_rest_state() {
  bool settled = max_speed2_ < kRestSpeed * kRestSpeed && std::abs(jaw_speed_) < kRestSpeed &&
                 std::abs(jaw_angle_ - jaw_target_) < kRestActivation;
  for (std::size_t i = 0; i < kMuscleCount && settled; ++i)
    settled = std::abs(activation_[i] - target_[i]) < kRestActivation;
  at_rest_ = settled;
}

void FaceSimulation::substep(float h) {
  if (options_.solver == Solver::projective) {
    FaceSimulation* self = this;
    ProjectiveStepper::substep(std::span<FaceSimulation* const>(&self, 1), h);
    return;
  }
  const std::array<float, kMuscleCount> before = activation_;
  update_muscles_and_jaw(h);
  place_bone(h);
  if (options_.solver == Solver::mass_spring) {
    mass_spring_substep(h);
    return;
  }
  // XPBD's ties act over the whole sub-step: they take the activation's
  // mean over it, not its end, so that a long sub-step does not pull ahead
  // of short ones. The activation approaches its target exponentially, so
  // its exact mean is the target less the gap times tau/h (1 - e^(-h/tau));
  // the trapezoid overshot it by up to a fifth with 15 ms muscles.
  std::array<float, kMuscleCount> mean;
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    const float gap = target_[i] - before[i];
    const float tau = std::max(gap > 0.0f ? options_.activation_time_s : options_.deactivation_time_s, 1e-4f);
    mean[i] = target_[i] - gap * (tau / h) * (1.0f - std::exp(-h / tau));
  }
  pbd_substep(h, mean);
}

void FaceSimulation::update_muscles_and_jaw(float h) {
  const ActivationRates rates = activation_rates(options_.activation_time_s, options_.deactivation_time_s, h);
  for (std::size_t i = 0; i < kMuscleCount; ++i) activation_[i] = follow_activation(activation_[i], target_[i], rates);
  // Semi-implicit: the speed first, then the angle with the new speed; in
  // pieces of at most 35 ms (h omega 0.7), since the update diverges once
  // h omega > 2 (a 0.1 s step) and rings well before.
  const int pieces = std::max(1, static_cast<int>(std::ceil(h * kJawOmega / 0.7f - 1e-4f)));
  const float piece = h / static_cast<float>(pieces);
  for (int k = 0; k < pieces; ++k) {
    jaw_speed_ += piece * (kJawOmega * kJawOmega * (jaw_target_ - jaw_angle_) - 2.0f * kJawOmega * jaw_speed_);
    jaw_angle_ = std::clamp(jaw_angle_ + piece * jaw_speed_, model_->jaw_min_rad, model_->jaw_max_rad);
  }
  jaw_cos_ = std::cos(jaw_angle_);
  jaw_sin_ = std::sin(jaw_angle_);
  const TissueModel& m = *model_;
  const float glide_range = m.jaw_max_rad - m.jaw_glide_onset_rad;
  jaw_glide_ = glide_range > 0.0f ? std::max(0.0f, (jaw_angle_ - m.jaw_glide_onset_rad) / glide_range) * m.jaw_glide
                                  : glm::vec3(0.0f);
}

glm::vec3 FaceSimulation::jaw_turned(const glm::vec3& p, float share) const {
  const TissueModel& m = *model_;
  const float qy = p.y - m.jaw_hinge.y, qz = p.z - m.jaw_hinge.z;
  const glm::vec3 turned(p.x, m.jaw_hinge.y + jaw_cos_ * qy - jaw_sin_ * qz, m.jaw_hinge.z + jaw_sin_ * qy + jaw_cos_ * qz);
  return p + share * (turned + jaw_glide_ - p);
}

std::array<glm::vec3, kMuscleCount> FaceSimulation::muscle_origins() const {
  std::array<glm::vec3, kMuscleCount> origin;
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    const float share = model_->muscles[i].origin_jaw_share;
    origin[i] = share > 0.0f ? jaw_turned(course_.origin[i], share) : course_.origin[i];
  }
  return origin;
}

// Moves node i to its rest place moved by `share` of the jaw and pushed
// `lift` along `normal`, keeping the speed of that move so that the dampers
// joined to it see the motion.
void FaceSimulation::move_node_with_jaw(std::size_t i, float share, float h, const glm::vec3& normal, float lift) {
  const TissueModel& m = *model_;
  const glm::vec3 p = jaw_turned({m.rest_x[i], m.rest_y[i], m.rest_z[i]}, share) + lift * normal;
  vx_[i] = (p.x - x_[i]) / h;
  vy_[i] = (p.y - y_[i]) / h;
  vz_[i] = (p.z - z_[i]) / h;
  x_[i] = p.x;
  y_[i] = p.y;
  z_[i] = p.z;
}

// The bone layer follows the mandible by each column's share, and rises
// over a contracting muscle's belly.
void FaceSimulation::place_bone(float h) {
  const TissueModel& m = *model_;
  const std::size_t base = m.moving_node_count;
  for (std::uint16_t v : m.moving_bone_columns) {
    const float share = m.jaw_share[v];
    const glm::vec3 n = m.skull_normal[v];
    const glm::vec3 turned = glm::vec3(n.x, jaw_cos_ * n.y - jaw_sin_ * n.z, jaw_sin_ * n.y + jaw_cos_ * n.z);
    skull_normal_[v] = glm::normalize(n + share * (turned - n));
    const float lift = m.bulge_depth[v] * activation_[m.bulge_muscle[v]];
    move_node_with_jaw(base + v, share, h, skull_normal_[v], lift);
  }
  // The pinned outline follows its bone.
  for (std::uint16_t i : m.pinned_nodes) {
    const std::size_t v = i % m.vertex_count;
    const float share = m.jaw_share[v];
    if (share <= 0.0f) continue;
    move_node_with_jaw(i, share, h, skull_normal_[v], 0.0f);
  }
}

void FaceSimulation::resolve_skull() {
  const TissueModel& m = *model_;
  const std::size_t nv = m.vertex_count, bone = m.moving_node_count;
  for (std::size_t layer = 0; layer < kMovingLayerCount; ++layer) {
    const float share = m.layer_min_height[layer];
    for (std::size_t v = 0; v < nv; ++v) {
      const std::size_t i = layer * nv + v, b = bone + v;
      if (m.inverse_mass[i] == 0.0f) continue;
      glm::vec3 p(x_[i], y_[i], z_[i]), vel(vx_[i], vy_[i], vz_[i]);
      if (!resolve_skull_contact({x_[b], y_[b], z_[b]}, skull_normal_[v], share * m.column_thickness[v], p, vel))
        continue;
      x_[i] = p.x, y_[i] = p.y, z_[i] = p.z;
      vx_[i] = vel.x, vy_[i] = vel.y, vz_[i] = vel.z;
    }
  }
}

void FaceSimulation::resolve_lips() {
  const TissueModel& m = *model_;
  for (const auto& [upper, lower] : m.lip_pairs)
    resolve_lip_contact(y_[upper], y_[lower], vy_[upper], vy_[lower], m.inverse_mass[upper], m.inverse_mass[lower]);
}

FaceMeasurement FaceSimulation::measure() {
  const TissueModel& m = *model_;
  const std::size_t n = m.vertex_count;
  // The displacement (3 #V floats) goes into the force scratch array, which
  // both solvers rewrite at the start of every sub-step: no allocation.
  float* d = fx_.data();
  assert(fx_.size() >= 3 * n);
  for (std::size_t v = 0; v < n; ++v) {
    d[3 * v + 0] = x_[v] - m.rest_x[v];
    d[3 * v + 1] = y_[v] - m.rest_y[v];
    d[3 * v + 2] = z_[v] - m.rest_z[v];
  }
  FaceMeasurement out;
  const double residual2 =
      project_onto_basis(m.basis, std::span<const float>(d, 3 * n), last_weights_);
  out.action_units = last_weights_;
  if (correctives_) out.corrective = project_corrective(*correctives_, std::span<const float>(d, 3 * n), last_weights_);
  out.residual_rms_mm = static_cast<float>(std::sqrt(residual2 / double(n)) * model::kMillimetresPerUnit);
  return out;
}

std::vector<glm::vec3> FaceSimulation::surface() const {
  std::vector<glm::vec3> out(model_->vertex_count);
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = node_position(v);
  return out;
}

double FaceSimulation::kinetic_energy() const {
  const TissueModel& m = *model_;
  const auto& inverse_mass = m.inverse_mass;
  double sum = 0.0;
  for (std::size_t i = 0; i < m.moving_node_count; ++i) {
    if (inverse_mass[i] == 0.0f) continue;  // held: moves only with the bone
    sum += (double(vx_[i]) * vx_[i] + double(vy_[i]) * vy_[i] + double(vz_[i]) * vz_[i]) / inverse_mass[i];
  }
  return 0.5 * sum;
}

float FaceSimulation::element_volume(std::size_t e) const {
  PrismNodes p;
  const auto nodes = model_->element(e);
  for (std::size_t k = 0; k < 6; ++k) p[k] = node_position(nodes[k]);
  return prism_volume(p);
}

float FaceSimulation::height_above_skull(std::size_t node) const {
  const std::size_t v = node % model_->vertex_count;
  return glm::dot(node_position(node) - node_position(model_->moving_node_count + v), skull_normal_[v]);
}

std::size_t FaceSimulation::state_bytes() const {
  std::size_t bytes = sizeof(*this);
  for (const auto* v : {&x_, &y_, &z_, &vx_, &vy_, &vz_, &fx_, &fy_, &fz_}) bytes += v->capacity() * sizeof(float);
  return bytes + skull_normal_.capacity() * sizeof(glm::vec3) + course_.memory_bytes() - sizeof(course_);
}

}  // namespace fw::physics
