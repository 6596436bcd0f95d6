#include "speech_through_tissue.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bench_failure.hpp"
#include "bench_rounding.hpp"
#include "vertex_error.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/tissue_model.hpp"
#include "fw/speech/phoneme_timing.hpp"
#include "fw/speech/speech_track.hpp"

namespace fw::bench {
namespace {

constexpr double kFrameS = 1.0 / 30.0;
// Read this far ahead, the track puts the physics jaw's peak within a
// frame of its own (read as it plays, 3-4 frames late), as a speaker's
// commands lead the movement they make.
constexpr double kLeadS = 0.1;
// Lines rich in bilabials (/p b m/), each closing the lips.
const char* const kLines[] = {"a baby bought a puppy, mom", "hello everyone, nice to see you",
                              "maybe the map is in the pub", "i miss them so much, but it will be fine"};
// A closure of the track's lips: a local minimum of their opening under this.
constexpr double kClosedMm = 1.5;

// The lips' opening (mm): the upper inner edge over the lower, over the
// lips' contact pairs (skin vertices).
double lip_gap_mm(const model::FaceShape& face, const physics::TissueModel& tissue) {
  double gap = 0.0;
  for (const auto& pair : tissue.lip_pairs) gap += face.positions[pair[0]].y - face.positions[pair[1]].y;
  return gap / double(tissue.lip_pairs.size()) * model::kMillimetresPerUnit;
}

// The shift of `a` against `b` (frames, within +-8) that correlates them best.
int best_lag(const std::vector<double>& a, const std::vector<double>& b) {
  int best = 0;
  double most = -1e300;
  for (int lag = -8; lag <= 8; ++lag) {
    double sum = 0.0;
    for (std::size_t f = 0; f < b.size(); ++f) {
      const long g = long(f) + lag;
      if (g >= 0 && g < long(a.size())) sum += a[std::size_t(g)] * b[f];
    }
    if (sum > most) most = sum, best = lag;
  }
  return best;
}

}  // namespace

nlohmann::json speech_through_tissue() {
  const model::AvatarModel avatar = model::generic_avatar_model();
  VertexError distance(avatar);
  double physics_gap = 0.0, track_gap = 0.0, lag = 0.0;
  std::size_t frames = 0, closures = 0;
  for (const char* line : kLines) {
    speech::PhonemeTiming timing;
    std::string error;
    if (!speech::time_phonemes(line, "en", speech::SpeechLimits{}, timing, error)) fail_bench("sim", error);
    const speech::SpeechTrack track = speech::speech_track(timing);
    physics::SimulationOptions options;
    options.solver = physics::Solver::projective;
    physics::FaceSimulation face(avatar, options);
    std::vector<double> gap_physics, gap_track, jaw_physics, jaw_track;
    for (double t = 0.0; t < track.length_s() + 0.5; t += kFrameS) {
      face.set_action_units(track.at(t + kLeadS));
      face.step(kFrameS);
      const physics::FaceMeasurement m = face.measure();
      codec::FaceParams physical, spoken;
      physical.au = m.action_units;
      physical.corrective = m.corrective;
      spoken.au = track.at(t);
      distance.add(spoken, physical);
      const model::FaceShape p = model::reconstruct_face(avatar, physical), s = model::reconstruct_face(avatar, spoken);
      gap_physics.push_back(lip_gap_mm(p, face.model()));
      gap_track.push_back(lip_gap_mm(s, face.model()));
      jaw_physics.push_back(physical.au_intensity(26));
      jaw_track.push_back(spoken.au_intensity(26));
    }
    for (std::size_t f = 2; f + 2 < gap_track.size(); ++f) {
      if (gap_track[f] >= kClosedMm || gap_track[f] > gap_track[f - 1] || gap_track[f] >= gap_track[f + 1]) continue;
      physics_gap += *std::min_element(gap_physics.begin() + long(f) - 2, gap_physics.begin() + long(f) + 3);
      track_gap += gap_track[f];
      ++closures;
    }
    lag += best_lag(jaw_physics, jaw_track);
    frames += gap_track.size();
  }
  const double lines = double(std::size(kLines));
  return {
      {"speech_frames", frames},
      {"speech_lead_ms", kLeadS * 1000.0},
      {"speech_vs_track_mm", rounded(distance.rms_mm())},
      {"speech_bilabial_gap_mm", closures ? rounded(physics_gap / double(closures)) : 0.0},
      {"speech_bilabial_gap_mm_track", closures ? rounded(track_gap / double(closures)) : 0.0},
      {"speech_jaw_lag_frames", rounded(lag / lines)},
  };
}

}  // namespace fw::bench
