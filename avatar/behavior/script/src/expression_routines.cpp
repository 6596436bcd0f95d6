#include "fw/script/expression_routines.hpp"

#include "fw/script/facs.hpp"
#include "fw/script/limits.hpp"
#include "routine_messages.hpp"

namespace fw::script {
namespace {

void open_animation(RoutineCall& call, bool clear) {
  KeyframeAnimation animation;
  animation.clear_frames = clear;
  animation.position = call.position;
  call.script.animation = std::move(animation);
}

SemanticValue clear_all_frames(RoutineCall& call) {
  open_animation(call, true);
  return {};
}

SemanticValue keep_all_frames(RoutineCall& call) {
  open_animation(call, false);
  return {};
}

SemanticValue begin_keyframe(RoutineCall& call) {
  auto& animation = call.script.animation;
  if (!animation) {
    misbound(call, "begin_keyframe", "an expression sentence (bind clear_all_frames or keep_all_frames first)");
    return {};
  }
  if (animation->keyframes.size() >= kMaxKeyframes) {
    call.diagnostics.error(call.position, "more than " + std::to_string(kMaxKeyframes) +
                                              " keyframes in one sentence; split it (KeepAllFrame continues from "
                                              "where the sentence before ended)");
    return {};
  }
  animation->keyframes.push_back({{}, call.position});
  return {};
}

SemanticValue au_intensity(RoutineCall& call) {
  const SemanticValue& number = call.values[0];
  const SemanticValue& strength = call.values[1];
  auto& animation = call.script.animation;
  if (!animation || animation->keyframes.empty()) {
    misbound(call, "au_intensity", "a keyframe (bind begin_keyframe to the production that starts one)");
    return {};
  }
  const std::int64_t au = number.integer;
  bool ok = true;
  if (!is_facs_action_unit(au)) {
    call.diagnostics.error(number.position, "AU " + std::to_string(au) + " is not a FACS action unit (FACS numbers are " +
                                                std::string(facs_ranges_text()) + ")");
    ok = false;
  }
  const double intensity = strength.number();
  if (!(intensity >= 0.0 && intensity <= kMaxAuIntensity)) {
    call.diagnostics.error(strength.position, "the intensity " + number_text(intensity) + " of AU " +
                                                  std::to_string(au) + " is out of range: write 0 to " +
                                                  number_text(kMaxAuIntensity) +
                                                  " (the paper's scale: 2 is the action unit at its full strength, "
                                                  "1 half of it)");
    ok = false;
  }
  Keyframe& keyframe = animation->keyframes.back();
  for (const AuIntensity& earlier : keyframe.aus) {
    if (earlier.au != au) continue;
    call.diagnostics.error(number.position, "AU " + std::to_string(au) + " appears twice in this keyframe (first at " +
                                                std::to_string(earlier.position.line) + ":" +
                                                std::to_string(earlier.position.column) + "); give it once");
    ok = false;
    break;
  }
  if (!ok) return {};
  const bool carried = is_carried_by_faces(au);
  if (!carried)
    call.diagnostics.warning(number.position, "AU " + std::to_string(au) + " (" +
                                                  std::string(facs_action_unit_name(au)) +
                                                  ") is a FACS action unit that facewire's faces do not show (they "
                                                  "show AUs " +
                                                  carried_action_units_text() +
                                                  "); it is kept in the keyframe but moves nothing");
  AuIntensity entry;
  entry.au = static_cast<int>(au);
  entry.intensity = intensity;
  entry.face_intensity = intensity / kMaxAuIntensity;
  entry.carried = carried;
  entry.position = number.position;
  keyframe.aus.push_back(entry);
  return {};
}

// Plays belong to the open expression sentence, or are the previews of the
// open AU definition: the paper ends both kinds of sentence with Animate.
std::vector<Play>* plays_of(RoutineCall& call, const char* routine, std::size_t& keyframes) {
  if (call.script.animation) {
    keyframes = call.script.animation->keyframes.size();
    return &call.script.animation->plays;
  }
  if (call.script.au_definition) {
    keyframes = 0;
    return &call.script.au_definition->previews;
  }
  misbound(call, routine, "an expression sentence or an AU definition");
  return nullptr;
}

bool steps_ok(RoutineCall& call, const SemanticValue& steps) {
  if (steps.integer >= 1 && steps.integer <= kMaxSteps) return true;
  call.diagnostics.error(steps.position, "the number of steps must be 1 to " + std::to_string(kMaxSteps) + ", not " +
                                             std::to_string(steps.integer));
  return false;
}

void add_play(RoutineCall& call, const char* routine, Play play) {
  std::size_t keyframes = 0;
  std::vector<Play>* plays = plays_of(call, routine, keyframes);
  if (!plays) return;
  if (plays->size() >= kMaxPlays) {
    call.diagnostics.error(call.position, "more than " + std::to_string(kMaxPlays) + " Animate and Hold statements in one sentence; split it");
    return;
  }
  play.keyframe_count = keyframes;
  play.position = call.position;
  plays->push_back(std::move(play));
}

SemanticValue animate(RoutineCall& call) {
  const SemanticValue& steps = call.values[0];
  const SemanticValue& shading = call.values[1];
  bool ok = steps_ok(call, steps);
  if (shading.kind == ValueKind::text && (shading.text.empty() || shading.text.size() > kMaxShadingBytes)) {
    call.diagnostics.error(shading.position, "the shading must be 1 to " + std::to_string(kMaxShadingBytes) +
                                                 " characters, e.g. \"Texture\" or \"SmoothShading\"");
    ok = false;
  }
  if (!ok) return {};
  Play play;
  play.kind = PlayKind::animate;
  play.steps = static_cast<int>(steps.integer);
  play.shading = shading.kind == ValueKind::text ? shading.text : "Texture";
  add_play(call, "animate", std::move(play));
  return {};
}

SemanticValue hold(RoutineCall& call) {
  if (!steps_ok(call, call.values[0])) return {};
  Play play;
  play.kind = PlayKind::hold;
  play.steps = static_cast<int>(call.values[0].integer);
  add_play(call, "hold", std::move(play));
  return {};
}

SemanticValue end_animation(RoutineCall& call) {
  auto& animation = call.script.animation;
  if (!animation) {
    misbound(call, "end_animation", "an expression sentence");
    return {};
  }
  call.script.meaning.animations.push_back(std::move(*animation));
  animation.reset();
  return {};
}

}  // namespace

void add_expression_routines(RoutineLibrary& library) {
  library.add({"clear_all_frames", {}, ValueKind::none, clear_all_frames,
               "opens an expression sentence that starts from the neutral face"});
  library.add({"keep_all_frames", {}, ValueKind::none, keep_all_frames,
               "opens an expression sentence that continues from the current frames"});
  library.add({"begin_keyframe", {}, ValueKind::none, begin_keyframe, "starts a keyframe"});
  library.add({"au_intensity",
               {{kIntegerParameter, "the action-unit number"}, {kNumberParameter, "its intensity"}},
               ValueKind::none,
               au_intensity,
               "sets one action unit of the keyframe"});
  library.add({"animate",
               {{kIntegerParameter, "the number of steps"}, {kTextParameter | kOptional, "the shading"}},
               ValueKind::none,
               animate,
               "plays through the keyframes so far, or previews an AU definition"});
  library.add({"hold", {{kIntegerParameter, "the number of steps"}}, ValueKind::none, hold,
               "stays on the last keyframe"});
  library.add({"end_animation", {}, ValueKind::none, end_animation, "closes an expression sentence"});
}

}  // namespace fw::script
