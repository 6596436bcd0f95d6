#include "fw/behavior/facs_track.hpp"

#include <algorithm>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"

namespace fw::behavior {
namespace {

// A keyframe on `base`: the AUs it lists set, the others as in `base`
// (ClearAllFrame's base is the neutral face, so keyframes are full poses).
AuTargets pose_of(const script::Keyframe& k, const AuTargets& base) {
  codec::FaceParams p;
  p.au = base;
  for (const script::AuIntensity& a : k.aus)
    if (a.carried) p.set_au(a.au, static_cast<float>(a.face_intensity));
  return p.au;
}

}  // namespace

AuTargets AuTrack::at(double t) const {
  if (times_s.empty() || t <= times_s.front()) return poses.empty() ? AuTargets{} : poses.front();
  if (t >= times_s.back()) return poses.back();
  const auto it = std::upper_bound(times_s.begin(), times_s.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - times_s.begin());
  const double s = (t - times_s[i - 1]) / std::max(1e-9, times_s[i] - times_s[i - 1]);
  AuTargets out{};
  for (std::size_t c = 0; c < out.size(); ++c)
    out[c] = poses[i - 1][c] + static_cast<float>(s) * (poses[i][c] - poses[i - 1][c]);
  return out;
}

AuTrack animation_track(const script::KeyframeAnimation& a, const AuTargets& current) {
  // KeepAllFrame continues from the face as the sentence finds it and comes
  // back to it; ClearAllFrame from and to the neutral face.
  const AuTargets base = a.clear_frames ? AuTargets{} : current;
  AuTrack t;
  t.times_s.push_back(0);
  t.poses.push_back(base);
  std::size_t played = 0;  // keyframes reached so far
  for (const script::Play& play : a.plays) {
    const double span = play.steps * AuTrack::kStepS;
    if (play.kind == script::PlayKind::hold || play.keyframe_count <= played) {
      t.times_s.push_back(t.times_s.back() + span);
      t.poses.push_back(t.poses.back());
      continue;
    }
    // Animate: through the keyframes written since the last play, evenly.
    const std::size_t n = std::min(play.keyframe_count, a.keyframes.size()) - played;
    for (std::size_t k = 0; k < n; ++k) {
      t.times_s.push_back(t.times_s.back() + span / static_cast<double>(n));
      t.poses.push_back(pose_of(a.keyframes[played + k], base));
    }
    played += n;
  }
  if (a.plays.empty() && !a.keyframes.empty()) {  // keyframes without a play: show the last
    t.times_s.push_back(0.3);
    t.poses.push_back(pose_of(a.keyframes.back(), base));
  }
  t.times_s.push_back(t.times_s.back() + AuTrack::kHoldS);
  t.poses.push_back(t.poses.back());
  t.times_s.push_back(t.times_s.back() + AuTrack::kReleaseS);
  t.poses.push_back(base);
  return t;
}

bool facs_track(std::string_view sentence, const AuTargets& current, AuTrack& track, std::string& error) {
  const script::ScriptResult result = script::parse_script(script::default_language(), sentence);
  for (const script::Diagnostic& d : result.diagnostics) {
    if (d.severity == script::Severity::error) {
      error = std::string("FACS sentence, line ") + std::to_string(d.position.line) + " column " + std::to_string(d.position.column) +
              ": " + d.message;
      return false;
    }
  }
  if (result.meaning.animations.empty()) {
    error = "no expression sentence (write e.g. ClearAllFrame BeginKeyFrame 12 1.0 Animate 5 \"Texture\" end)";
    return false;
  }
  track = animation_track(result.meaning.animations.front(), current);
  return true;
}

bool facs_track(std::string_view sentence, AuTrack& track, std::string& error) {
  return facs_track(sentence, AuTargets{}, track, error);
}

AuTrack expression_track(model::Expression expression, float intensity, double seconds) {
  // As fast in and out as the emotion model's expressions (expression_envelope).
  constexpr double kEaseS = 0.4;
  codec::FaceParams pose;
  model::apply_expression(expression, intensity, pose);
  AuTrack track;
  track.times_s = {0.0, kEaseS, kEaseS + seconds, 2 * kEaseS + seconds};
  track.poses = {AuTargets{}, pose.au, pose.au, AuTargets{}};
  return track;
}

}  // namespace fw::behavior
