#include "fw/behavior/action_selection.hpp"

#include <algorithm>
#include <cmath>

#include "fw/behavior/spontaneous_display.hpp"

namespace fw::behavior {
namespace {

constexpr std::string_view kRoutineNames[] = {"visual_search", "attentive", "snubbing",
                                              "expressive",    "mimicking", "interactive"};

float angle_between(YawPitch a, YawPitch b) { return std::hypot(a.yaw_rad - b.yaw_rad, a.pitch_rad - b.pitch_rad); }

}  // namespace

std::string_view routine_name(Routine r) { return kRoutineNames[static_cast<std::size_t>(r)]; }

ActionSelection::ActionSelection(std::uint64_t seed) : rng_(seed) {}

double ActionSelection::uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

void ActionSelection::set_leader(bool leader, std::optional<FaceId> leader_id) {
  leader_ = leader;
  leader_id_ = leader_id;
}

void ActionSelection::look_at(FaceId face, double seconds) { override_ = Override{Routine::attentive, face, now_s_ + seconds}; }
void ActionSelection::snub(FaceId face, double seconds) { override_ = Override{Routine::snubbing, face, now_s_ + seconds}; }
void ActionSelection::hold_expression(double seconds) { hold_expression_until_s_ = now_s_ + seconds; }

void ActionSelection::draw_attention(FaceId writer, double seconds) {
  if (override_ && override_->until_s > now_s_) return;  // a person's command in force wins
  override_ = Override{Routine::attentive, writer, now_s_ + seconds};
}

const PerceivedFace* ActionSelection::find(const std::vector<PerceivedFace>& seen, std::optional<FaceId> id) const {
  if (!id) return nullptr;
  for (const PerceivedFace& f : seen)
    if (f.id == *id) return &f;
  return nullptr;
}

bool ActionSelection::clear_of(YawPitch c, const PerceivedFace* avoided) const {
  if (!avoided) return true;
  if (angle_between(c, avoided->direction) < kSnubClearanceRad) return false;
  // Stay on the side the gaze is on, so no gaze shift sweeps across the
  // avoided face.
  const float side = gaze_.yaw_rad - avoided->direction.yaw_rad;
  return (c.yaw_rad - avoided->direction.yaw_rad) * (side == 0 ? 1.0f : side) > 0;
}

void ActionSelection::search(Intent& intent, const std::vector<PerceivedFace>& seen, std::optional<FaceId> avoid) {
  const PerceivedFace* avoided = find(seen, avoid);
  const bool point_blocked = !search_face_ && !clear_of(direction_angles(search_point_), avoided);
  const bool face_blocked = search_face_ && (search_face_ == avoid || !clear_of(find(seen, search_face_) ? find(seen, search_face_)->direction : YawPitch{}, avoided));
  if (now_s_ >= search_until_s_ || (search_face_ && !find(seen, search_face_)) || point_blocked || face_blocked) {
    search_until_s_ = now_s_ + uniform(kSearchDwellMinS, kSearchDwellMaxS);
    search_face_.reset();
    // Scan the faces in view more often than empty space: they carry the news.
    std::vector<const PerceivedFace*> candidates;
    // Not the face just attended: search moves on (fatigue holds here too).
    for (const PerceivedFace& f : seen)
      if ((!avoid || f.id != *avoid) && f.id != attending_ && clear_of(f.direction, avoided)) candidates.push_back(&f);
    if (!candidates.empty() && uniform(0, 1) < 0.7) {
      search_face_ = candidates[static_cast<std::size_t>(uniform(0, static_cast<double>(candidates.size()) - 1e-9))]->id;
    } else {
      // Mostly ahead; wider (head and eyes together) when avoiding a face
      // leaves no room ahead, and as a last resort just clear of it.
      YawPitch d{};
      bool found = false;
      for (int attempt = 0; attempt < 64 && !found; ++attempt) {
        const double wide = attempt < 24 ? 0.9 : 1.5;
        d = {static_cast<float>(uniform(-wide, wide)), static_cast<float>(uniform(-0.2, 0.25))};
        found = clear_of(d, avoided);
      }
      if (!found && avoided) {
        const float side = gaze_.yaw_rad >= avoided->direction.yaw_rad ? 1.0f : -1.0f;
        d = {avoided->direction.yaw_rad + side * (kSnubClearanceRad + 0.2f), 0.0f};
      }
      search_point_ = head_geometry().eye_mid_mm + direction_from_angles(d) * static_cast<float>(uniform(900, 2000));
    }
  }
  intent.attend = search_face_;
  intent.look_seat_mm = search_point_;
}

void ActionSelection::schedule_expression(Intent& intent, bool performing, const EmotionPoint& felt) {
  if (performing || now_s_ < hold_expression_until_s_) {
    next_expression_s_ = std::max(next_expression_s_, now_s_ + uniform(0.4, 1.2));
    return;
  }
  if (now_s_ < next_expression_s_) return;
  // The expressive routine shows what the face feels, or a social smile
  // (spontaneous_display.hpp), now and then.
  const Display display = spontaneous_display(felt, rng_);
  intent.perform = display.primary;
  intent.perform_envelope = display.envelope;
  next_expression_s_ = now_s_ + display.envelope.length_s() + next_display_after_s(rng_);
}

void ActionSelection::lead(Intent& intent, const std::vector<PerceivedFace>& seen, bool performing,
                           const EmotionPoint& felt) {
  if (seen.empty()) {
    partner_.reset();
    intent.routine = Routine::visual_search;
    return search(intent, seen, std::nullopt);
  }
  if (now_s_ < glance_until_s_) {
    intent.routine = Routine::visual_search;
    return search(intent, seen, partner_);
  }
  const bool lost = !find(seen, partner_);
  const double limit = seen.size() == 1 ? kAttendMaxS : 0.0;
  if (!lost && seen.size() == 1 && now_s_ - partner_since_s_ >= limit) {
    // Fatigue with a single partner: look away for a moment, then come back.
    glance_until_s_ = now_s_ + kGlanceAwayS;
    partner_since_s_ = glance_until_s_;
    intent.routine = Routine::visual_search;
    return search(intent, seen, partner_);
  }
  if (lost || (seen.size() > 1 && now_s_ >= turn_until_s_)) {
    // The next turn goes to the face attended least recently.
    const PerceivedFace* next = nullptr;
    double oldest = 1e300;
    for (const PerceivedFace& f : seen) {
      if (seen.size() > 1 && partner_ && f.id == *partner_) continue;
      double last = -1e9;
      for (const auto& [id, at] : last_attended_)
        if (id == f.id) last = at;
      if (last < oldest) {
        oldest = last;
        next = &f;
      }
    }
    partner_ = next->id;
    partner_since_s_ = now_s_;
    turn_until_s_ = now_s_ + uniform(kLeaderTurnMinS, kLeaderTurnMaxS);
  }
  std::erase_if(last_attended_, [&](const auto& e) { return e.first == *partner_; });
  last_attended_.emplace_back(*partner_, now_s_);
  intent.routine = seen.size() > 1 ? Routine::interactive : Routine::expressive;
  intent.attend = partner_;
  schedule_expression(intent, performing, felt);
}

void ActionSelection::follow(Intent& intent, const std::vector<PerceivedFace>& seen) {
  const PerceivedFace* leader = find(seen, leader_id_);
  if (now_s_ < rest_until_s_) {
    // Tired of the leader: attend a different face, or search away from it.
    if (!find(seen, rest_face_)) {
      rest_face_.reset();
      for (const PerceivedFace& f : seen)
        if (!leader_id_ || f.id != *leader_id_) {
          rest_face_ = f.id;
          break;
        }
    }
    if (rest_face_) {
      intent.routine = Routine::attentive;
      intent.attend = rest_face_;
    } else {
      intent.routine = Routine::visual_search;
      search(intent, seen, leader_id_);
    }
    return;
  }
  const bool attended = leader && leader->looks_at_me;
  if (attended) {
    if (leader_attention_since_s_ < 0) leader_attention_since_s_ = now_s_;
    leader_away_since_s_ = -1;
  } else {
    leader_attention_since_s_ = -1;
    if (leader_away_since_s_ < 0) leader_away_since_s_ = now_s_;
  }
  // Engaged: from the leader's attention until the leader has looked away for
  // a second (a glance elsewhere does not break the exchange).
  const bool engage = leader && (attended || (engaged_since_s_ >= 0 && now_s_ - leader_away_since_s_ < 1.0));
  if (!engage) {
    engaged_since_s_ = -1;
    intent.routine = Routine::visual_search;
    return search(intent, seen, std::nullopt);
  }
  if (engaged_since_s_ < 0) engaged_since_s_ = now_s_;
  if (now_s_ - engaged_since_s_ >= kMimicMaxS) {
    // Behavior fatigue: disengage the leader.
    engaged_since_s_ = -1;
    rest_until_s_ = now_s_ + kRestS;
    rest_face_.reset();
    return follow(intent, seen);
  }
  intent.attend = leader->id;
  if (now_s_ - engaged_since_s_ >= kEngageAfterS) {
    intent.routine = Routine::mimicking;
    intent.mimic = leader->id;
  } else {
    intent.routine = Routine::attentive;
  }
}

Intent ActionSelection::step(double dt_s, const std::vector<PerceivedFace>& seen, YawPitch gaze, bool performing,
                             const EmotionPoint& felt) {
  now_s_ += dt_s;
  gaze_ = gaze;
  Intent intent;
  intent.look_seat_mm = search_point_;
  if (override_ && now_s_ >= override_->until_s) override_.reset();
  if (override_) {
    intent.routine = override_->routine;
    if (override_->routine == Routine::attentive) {
      intent.attend = override_->face;  // the room knows where, even out of view
    } else {
      // Snubbing: look anywhere but at the snubbed face.
      search(intent, seen, override_->face);
    }
  } else if (leader_) {
    lead(intent, seen, performing, felt);
  } else {
    follow(intent, seen);
  }
  if (now_s_ < hold_expression_until_s_) {
    intent.perform.reset();
    intent.mimic.reset();
  }
  routine_ = intent.routine;
  attending_ = intent.attend;
  return intent;
}

}  // namespace fw::behavior
