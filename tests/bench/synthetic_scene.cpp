#include "synthetic_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "splitmix_random.hpp"

namespace fw::bench {
namespace {

using codec::AuSide;
using codec::FaceParams;

constexpr double kDeg = std::numbers::pi / 180.0;

using Random = SplitMixRandom;

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// Minimum-jerk position profile over [0,1]: the shape of a saccade.
double min_jerk(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
}

// Smooth noise: a few sines with random frequencies and phases, about
// `amplitude` at most (low-level "Perlin" perturbation of the head).
struct Wobble {
  std::array<double, 3> frequency_hz{}, phase{}, weight{};
  double amplitude = 0;
  Wobble() = default;
  Wobble(Random& r, double amp, double f_lo, double f_hi) : amplitude(amp) {
    for (std::size_t i = 0; i < 3; ++i) {
      frequency_hz[i] = r.uniform(f_lo, f_hi);
      phase[i] = r.uniform(0.0, 2.0 * std::numbers::pi);
      weight[i] = r.uniform(0.5, 1.0);
    }
  }
  double at(double t) const {
    double sum = 0, total = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      sum += weight[i] * std::sin(2.0 * std::numbers::pi * frequency_hz[i] * t + phase[i]);
      total += weight[i];
    }
    return total > 0 ? amplitude * sum / total : 0.0;
  }
};

struct AuWeight {
  int au;
  AuSide side;  // both: every side the AU has
  double weight;
};

struct Template {
  const char* name;
  std::vector<AuWeight> aus;
};

const std::vector<Template>& templates() {
  static const std::vector<Template> t = {
      {"happiness", {{6, AuSide::both, 0.6}, {12, AuSide::both, 1.0}, {25, AuSide::both, 0.4}}},
      {"surprise", {{1, AuSide::both, 0.9}, {2, AuSide::both, 0.9}, {5, AuSide::both, 0.6}, {25, AuSide::both, 0.5},
                    {26, AuSide::both, 0.7}}},
      {"sadness", {{1, AuSide::both, 0.8}, {4, AuSide::both, 0.6}, {15, AuSide::both, 0.8}, {17, AuSide::both, 0.4}}},
      {"anger", {{4, AuSide::both, 1.0}, {5, AuSide::both, 0.5}, {7, AuSide::both, 0.7}, {23, AuSide::both, 0.8},
                 {24, AuSide::both, 0.5}}},
      {"disgust", {{9, AuSide::both, 0.9}, {10, AuSide::both, 0.7}, {15, AuSide::both, 0.4}, {17, AuSide::both, 0.5}}},
      {"fear", {{1, AuSide::both, 0.8}, {2, AuSide::both, 0.6}, {4, AuSide::both, 0.5}, {5, AuSide::both, 0.9},
                {20, AuSide::both, 0.7}, {25, AuSide::both, 0.5}, {26, AuSide::both, 0.4}}},
      {"smirk", {{12, AuSide::left, 0.7}, {14, AuSide::left, 0.6}}},
  };
  return t;
}

struct Episode {
  double start, onset, hold, release;
  double intensity;
  double left_scale = 1, right_scale = 1;
  const Template* expression;
  double envelope(double t) const {
    const double u = t - start;
    if (u <= 0) return 0;
    if (u < onset) return smoothstep(u / onset);
    if (u < onset + hold) return 1.0 - 0.15 * (u - onset) / hold;  // a slight sag while held
    return 0.85 * (1.0 - smoothstep((u - onset - hold) / release));
  }
  double end() const { return start + onset + hold + release; }
};

struct Fixation {
  double start;            // saccade onset
  double saccade_s;        // main-sequence duration
  double yaw, pitch;       // gaze direction, rad
  double vergence;         // rad
  double head_yaw, head_pitch;  // where the head heads for
};

struct Blink {
  double start, close_s, closed_s, open_s, depth;
  double at(double t) const {
    const double u = t - start;
    if (u <= 0) return 0;
    if (u < close_s) return depth * smoothstep(u / close_s);
    if (u < close_s + closed_s) return depth;
    return depth * (1.0 - smoothstep((u - close_s - closed_s) / open_s));
  }
};

struct Vascular {
  double start = -1, onset = 0, sustain = 0, release = 0;
  bool pallor = false;
  double peak = 0;
  double envelope(double t) const {
    if (start < 0) return 0;
    const double u = t - start;
    if (u <= 0) return 0;
    if (u < onset) return smoothstep(u / onset);
    if (u < onset + sustain) return 1.0;
    return 1.0 - smoothstep((u - onset - sustain) / release);
  }
};

class AvatarScript {
 public:
  AvatarScript(Random& r, int index, int avatars, bool idle, double seconds) : idle_(idle) {
    head_wobble_ = {Wobble(r, (idle ? 0.15 : 0.3) * kDeg, 0.08, 0.4), Wobble(r, (idle ? 0.15 : 0.3) * kDeg, 0.08, 0.4),
                    Wobble(r, (idle ? 0.1 : 0.2) * kDeg, 0.08, 0.3)};
    sway_ = {Wobble(r, idle ? 0.5 : 1.5, 0.05, 0.2), Wobble(r, idle ? 0.5 : 1.0, 0.05, 0.2),
             Wobble(r, idle ? 0.5 : 1.5, 0.05, 0.2)};
    breath_hz_ = r.uniform(0.2, 0.3);
    breath_mm_ = idle ? 0.6 : 1.0;
    drift_ = {Wobble(r, 0.05 * kDeg, 0.2, 0.8), Wobble(r, 0.05 * kDeg, 0.2, 0.8)};
    make_gaze(r, index, avatars, seconds);
    make_blinks(r, seconds);
    if (!idle) {
      make_expressions(r, seconds);
      vascular_.pallor = index % 2 == 1;
      vascular_.start = r.uniform(5.0, 35.0);
      vascular_.onset = vascular_.pallor ? r.uniform(1.0, 2.0) : r.uniform(1.5, 3.0);
      vascular_.sustain = r.uniform(4.0, 10.0);
      vascular_.release = r.uniform(4.0, 8.0);
      vascular_.peak = vascular_.pallor ? r.uniform(0.3, 0.6) : r.uniform(0.4, 0.8);
    }
  }

  FaceParams at(double t) const {
    FaceParams p;
    for (const Episode& e : episodes_) {
      const double env = e.envelope(t);
      if (env <= 0) continue;
      for (const AuWeight& w : e.expression->aus) {
        const double v = e.intensity * w.weight * env;
        add_au(p, w, v * e.left_scale, v * e.right_scale);
      }
    }
    for (float& a : p.au) a = std::clamp(a, 0.0f, 1.0f);

    // Gaze: the current fixation, reached through a saccade from the last one;
    // the head approaches its target exponentially and the eyes make up the
    // rest, so the gaze holds while the head still moves.
    std::size_t i = 0;
    while (i + 1 < fixations_.size() && fixations_[i + 1].start <= t) ++i;
    const Fixation& f = fixations_[i];
    const Fixation& prev = i > 0 ? fixations_[i - 1] : f;
    const double s = min_jerk((t - f.start) / f.saccade_s);
    double gaze_yaw = prev.yaw + (f.yaw - prev.yaw) * s;
    double gaze_pitch = prev.pitch + (f.pitch - prev.pitch) * s;
    const double vergence = prev.vergence + (f.vergence - prev.vergence) * s;
    gaze_yaw += drift_[0].at(t) + microsaccade(t, 0);
    gaze_pitch += drift_[1].at(t) + microsaccade(t, 1);
    const double head_delay = 0.05;
    const double h = t - f.start - head_delay;
    const double approach = h > 0 ? 1.0 - std::exp(-h / head_tau_) : 0.0;
    const double head_yaw = prev_head_yaw(i) + (f.head_yaw - prev_head_yaw(i)) * approach;
    const double head_pitch = prev_head_pitch(i) + (f.head_pitch - prev_head_pitch(i)) * approach;
    p.head_yaw_rad = static_cast<float>(head_yaw + head_wobble_[0].at(t));
    p.head_pitch_rad = static_cast<float>(head_pitch + head_wobble_[1].at(t));
    p.head_roll_rad = static_cast<float>(head_wobble_[2].at(t));
    const double eye_yaw = gaze_yaw - p.head_yaw_rad;
    const double eye_pitch = gaze_pitch - p.head_pitch_rad;
    p.eye_left.yaw_rad = static_cast<float>(std::clamp(eye_yaw - vergence / 2, -0.6, 0.6));
    p.eye_right.yaw_rad = static_cast<float>(std::clamp(eye_yaw + vergence / 2, -0.6, 0.6));
    p.eye_left.pitch_rad = p.eye_right.pitch_rad = static_cast<float>(std::clamp(eye_pitch, -0.5, 0.5));

    p.head_translation_mm[0] = static_cast<float>(sway_[0].at(t));
    p.head_translation_mm[1] =
        static_cast<float>(sway_[1].at(t) + breath_mm_ * std::sin(2 * std::numbers::pi * breath_hz_ * t));
    p.head_translation_mm[2] = static_cast<float>(sway_[2].at(t));

    // Lids: blinks, plus the upper lid following the eye down (lid-eye coupling).
    double lid = 0;
    for (const Blink& b : blinks_) lid = std::max(lid, b.at(t));
    const double droop = 0.4 * std::max(0.0, -eye_pitch);
    p.lid_left = p.lid_right = static_cast<float>(std::clamp(lid + droop, 0.0, 1.0));

    const double v = vascular_.envelope(t) * vascular_.peak;
    if (vascular_.pallor) {
      p.pallor = static_cast<float>(v);
    } else {
      const double region[codec::kColourRegionCount] = {0.3, 1.0, 1.0, 0.5, 0.25};  // forehead, cheeks, nose, sides
      for (std::size_t k = 0; k < codec::kColourRegionCount; ++k) p.blush[k] = static_cast<float>(v * region[k]);
    }
    return p;
  }

 private:
  static void add_au(FaceParams& p, const AuWeight& w, double left, double right) {
    if (!codec::is_bilateral(w.au)) {
      p.au[static_cast<std::size_t>(codec::au_channel(w.au, AuSide::both))] += static_cast<float>(0.5 * (left + right));
      return;
    }
    if (w.side != AuSide::right)
      p.au[static_cast<std::size_t>(codec::au_channel(w.au, AuSide::left))] += static_cast<float>(left);
    if (w.side != AuSide::left)
      p.au[static_cast<std::size_t>(codec::au_channel(w.au, AuSide::right))] += static_cast<float>(right);
  }

  double prev_head_yaw(std::size_t i) const { return i > 0 ? head_reached_[i - 1].first : 0.0; }
  double prev_head_pitch(std::size_t i) const { return i > 0 ? head_reached_[i - 1].second : 0.0; }

  void make_gaze(Random& r, int index, int avatars, double seconds) {
    head_tau_ = r.uniform(0.15, 0.3);
    double t = 0;
    Fixation f{0, 0.05, 0, -2 * kDeg, 2 * std::atan(0.0315 / 1.5), 0, 0};
    fixations_.push_back(f);
    head_reached_.push_back({0, 0});
    while (t < seconds) {
      t += idle_ ? std::max(2.0, r.exponential(8.0)) : std::max(0.3, r.exponential(1.4));
      Fixation n;
      n.start = t;
      if (idle_) {
        n.yaw = r.uniform(-5, 5) * kDeg;
        n.pitch = r.uniform(-6, 1) * kDeg;
      } else if (avatars > 1 && r.chance(0.6)) {
        int other = r.pick(avatars - 1);
        if (other >= index) ++other;
        n.yaw = std::clamp((other - index) * 14.0, -35.0, 35.0) * kDeg + r.uniform(-2, 2) * kDeg;
        n.pitch = r.uniform(-4, 2) * kDeg;
      } else {
        n.yaw = r.uniform(-30, 30) * kDeg;
        n.pitch = r.uniform(-15, 8) * kDeg;
      }
      const double distance_m = r.uniform(0.8, 3.0);
      n.vergence = 2 * std::atan(0.0315 / distance_m);
      const Fixation& last = fixations_.back();
      const double amplitude_deg = std::hypot(n.yaw - last.yaw, n.pitch - last.pitch) / kDeg;
      n.saccade_s = 0.021 + 0.0022 * amplitude_deg;  // the main sequence
      // Large shifts bring the head along (about half of the way); small ones are eyes only.
      const auto [head_yaw, head_pitch] = head_reached_.back();
      if (amplitude_deg > 12) {
        n.head_yaw = 0.5 * n.yaw;
        n.head_pitch = 0.4 * n.pitch;
      } else {
        n.head_yaw = head_yaw;
        n.head_pitch = head_pitch;
      }
      fixations_.push_back(n);
      head_reached_.push_back({n.head_yaw, n.head_pitch});
      if (amplitude_deg > 20 && r.chance(0.4)) gaze_blinks_.push_back(t);
    }
    double m = 0;
    while (m < seconds) {
      m += r.uniform(0.8, 2.5);
      const double angle = r.uniform(0, 2 * std::numbers::pi);
      const double size = r.uniform(0.15, 0.4) * kDeg;
      microsaccades_.push_back({m, {size * std::cos(angle), size * std::sin(angle)}});
    }
  }

  // Microsaccades recentre the gaze: each is a quick step that returns
  // over the following half second (the drift it corrects).
  double microsaccade(double t, int axis) const {
    double sum = 0;
    for (const auto& [start, offset] : microsaccades_) {
      const double u = t - start;
      if (u <= 0 || u > 0.6) continue;
      const double v = offset[static_cast<std::size_t>(axis)];
      sum += u < 0.025 ? v * min_jerk(u / 0.025) : v * (1.0 - smoothstep((u - 0.025) / 0.5));
    }
    return sum;
  }

  void make_blinks(Random& r, double seconds) {
    std::vector<double> starts = gaze_blinks_;
    for (double t = r.uniform(0.5, 2.0); t < seconds; t += std::max(1.2, r.exponential(idle_ ? 4.5 : 3.5)))
      starts.push_back(t);
    std::sort(starts.begin(), starts.end());
    for (double s : starts)
      blinks_.push_back({s, r.uniform(0.08, 0.12), r.uniform(0.03, 0.07), r.uniform(0.12, 0.2),
                         r.chance(0.85) ? 1.0 : r.uniform(0.7, 0.95)});
  }

  void make_expressions(Random& r, double seconds) {
    const auto& all = templates();
    for (double t = r.uniform(0.5, 3.0); t < seconds;) {
      Episode e;
      e.start = t;
      e.expression = &all[static_cast<std::size_t>(r.pick(static_cast<int>(all.size())))];
      e.intensity = r.uniform(0.4, 1.0);
      e.onset = r.uniform(0.25, 0.8);
      e.hold = r.uniform(1.0, 4.0);
      e.release = r.uniform(0.5, 1.5);
      if (r.chance(0.3)) (r.chance(0.5) ? e.left_scale : e.right_scale) = r.uniform(0.5, 0.9);
      episodes_.push_back(e);
      t = e.end() + r.uniform(0.5, 4.0);
    }
  }

  bool idle_;
  std::array<Wobble, 3> head_wobble_, sway_;
  std::array<Wobble, 2> drift_;
  double breath_hz_ = 0.25, breath_mm_ = 1.0, head_tau_ = 0.2;
  std::vector<Fixation> fixations_;
  std::vector<std::pair<double, double>> head_reached_;
  std::vector<std::pair<double, std::array<double, 2>>> microsaccades_;
  std::vector<double> gaze_blinks_;
  std::vector<Blink> blinks_;
  std::vector<Episode> episodes_;
  Vascular vascular_;
};

}  // namespace

Scene make_synthetic_scene(const SyntheticSceneOptions& options) {
  Scene scene;
  scene.name = "synthetic-seed" + std::to_string(options.seed);
  scene.fps = options.fps;
  const int total = options.active_avatars + options.idle_avatars;
  const auto ticks = static_cast<std::size_t>(std::llround(options.seconds * options.fps));
  Random random(options.seed);
  for (int a = 0; a < total; ++a) {
    const bool idle = a >= options.active_avatars;
    Random own(random.next());  // each avatar its own stream: adding one leaves the others alone
    const AvatarScript script(own, a, total, idle, options.seconds);
    SceneAvatar avatar;
    avatar.name = (idle ? "idle-" : "avatar-") + std::to_string(a);
    avatar.idle = idle;
    avatar.ticks.reserve(ticks);
    for (std::size_t t = 0; t < ticks; ++t) avatar.ticks.push_back(script.at(static_cast<double>(t) / options.fps));
    scene.avatars.push_back(std::move(avatar));
  }
  return scene;
}

}  // namespace fw::bench
