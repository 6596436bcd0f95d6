#include "fw/script/vascular_routines.hpp"

#include <algorithm>
#include <cmath>

#include "fw/script/limits.hpp"
#include "fw/script/region_names.hpp"
#include "routine_messages.hpp"

namespace fw::script {
namespace {

bool unit_interval(RoutineCall& call, const SemanticValue& v, const std::string& what) {
  const double x = v.number();
  if (x >= 0.0 && x <= 1.0) return true;
  call.diagnostics.error(v.position, what + " " + number_text(x) + " is out of range: write 0 to 1");
  return false;
}

SemanticValue begin_emotion(RoutineCall& call) {
  VascularEmotion emotion;
  emotion.name = call.values[0].text;
  emotion.position = call.position;
  call.script.emotion = std::move(emotion);
  return {};
}

SemanticValue begin_stage(RoutineCall& call) {
  auto& emotion = call.script.emotion;
  if (!emotion) {
    misbound(call, "begin_stage", "an emotion (bind begin_emotion first)");
    return {};
  }
  const SemanticValue& name = call.values[0];
  const SemanticValue& duration = call.values[1];
  if (emotion->stages.size() >= kMaxStages) {
    call.diagnostics.error(name.position, "more than " + std::to_string(kMaxStages) + " stages in one emotion");
    return {};
  }
  for (const EmotionStage& earlier : emotion->stages) {
    if (earlier.name != name.text) continue;
    call.diagnostics.error(name.position, "emotion '" + emotion->name + "' already has a stage '" + printable(name.text) +
                                              "' at " + at_text(earlier.position) + "; name each stage once");
    return {};
  }
  const double d = duration.number();
  if (!(d > 0.0 && d <= 100.0)) {
    call.diagnostics.error(duration.position, "the duration " + number_text(d) +
                                                  " is out of range: a stage lasts more than 0 and at most 100 "
                                                  "percent of the episode");
  }
  EmotionStage stage;
  stage.name = name.text;
  stage.duration_percent = d;
  stage.position = name.position;
  emotion->stages.push_back(std::move(stage));
  return {};
}

SemanticValue stage_expression(RoutineCall& call) {
  auto& emotion = call.script.emotion;
  if (!emotion || emotion->stages.empty()) {
    misbound(call, "stage_expression", "a stage (bind begin_stage first)");
    return {};
  }
  EmotionStage& stage = emotion->stages.back();
  stage.expression = call.values[0].text;
  if (unit_interval(call, call.values[1], "the intensity")) stage.intensity = call.values[1].number();
  return {};
}

SemanticValue end_emotion(RoutineCall& call) {
  auto& emotion = call.script.emotion;
  if (!emotion) {
    misbound(call, "end_emotion", "an emotion");
    return {};
  }
  if (emotion->stages.empty()) {
    call.diagnostics.error(emotion->position, "emotion '" + printable(emotion->name) +
                                                  "' has no stages; give it at least one, e.g. [stage1 duration 100 "
                                                  "[expression NAME intensity 1]]");
    return {};
  }
  double total = 0;
  for (EmotionStage& stage : emotion->stages) {
    stage.start_percent = total;
    total += stage.duration_percent;
    stage.end_percent = total;
  }
  if (std::abs(total - 100.0) > 1e-6) {
    call.diagnostics.error(emotion->position, "the stages of emotion '" + printable(emotion->name) + "' last " +
                                                  number_text(total) +
                                                  " percent in all; durations are percentages of the episode and must "
                                                  "add up to 100");
    return {};
  }
  for (const VascularEmotion& earlier : call.script.meaning.emotions) {
    if (earlier.name != emotion->name) continue;
    call.diagnostics.error(emotion->position, "emotion '" + printable(emotion->name) + "' is already defined at " +
                                                  at_text(earlier.position) + "; define it once");
    return {};
  }
  // The intensity envelope of Figure 4: 0 at the start, then each stage ends
  // on its expression's intensity; a stage without one releases to 0.
  emotion->envelope.push_back({0.0, 0.0});
  for (const EmotionStage& stage : emotion->stages)
    emotion->envelope.push_back({stage.end_percent, stage.expression.empty() ? 0.0 : stage.intensity});
  call.script.meaning.emotions.push_back(std::move(*emotion));
  emotion.reset();
  return {};
}

SemanticValue begin_vascular_expression(RoutineCall& call) {
  VascularExpression expression;
  expression.name = call.values[0].text;
  expression.position = call.position;
  call.script.vascular_expression = std::move(expression);
  return {};
}

SemanticValue mpca_intensity(RoutineCall& call) {
  auto& expression = call.script.vascular_expression;
  if (!expression) {
    misbound(call, "mpca_intensity", "a vascular expression (bind begin_vascular_expression first)");
    return {};
  }
  const SemanticValue& region = call.values[0];
  const std::vector<std::size_t> channels = colour_channels_for(region.text);
  bool ok = true;
  if (channels.empty()) {
    call.diagnostics.error(region.position, "unknown colour region '" + printable(region.text) + "'; regions are " +
                                                colour_region_names_text() + " (case does not matter)");
    ok = false;
  }
  ok = unit_interval(call, call.values[1], "the intensity") && ok;
  if (!ok) return {};
  RegionIntensity entry;
  entry.region = region.text;
  entry.intensity = call.values[1].number();
  entry.position = region.position;
  for (std::size_t c : channels) entry.channels.emplace_back(colour_channel_name(c));
  // "nose" and "Nose" are one region; "head" and "cheeks" overlap but differ.
  for (const RegionIntensity& earlier : expression->regions) {
    if (earlier.channels != entry.channels) continue;
    call.diagnostics.error(region.position, "region '" + printable(region.text) + "' already has an intensity at " +
                                                at_text(earlier.position) + "; give it once");
    return {};
  }
  if (expression->regions.size() >= kMaxMpcas) {
    call.diagnostics.error(region.position, "more than " + std::to_string(kMaxMpcas) + " regions in one expression");
    return {};
  }
  // Overlapping regions (head and cheeks) do not add up: the stronger wins.
  for (std::size_t c : channels) expression->channels[c] = std::max(expression->channels[c], entry.intensity);
  expression->regions.push_back(std::move(entry));
  return {};
}

SemanticValue end_vascular_expression(RoutineCall& call) {
  auto& expression = call.script.vascular_expression;
  if (!expression) {
    misbound(call, "end_vascular_expression", "a vascular expression");
    return {};
  }
  for (const VascularExpression& earlier : call.script.meaning.vascular_expressions) {
    if (earlier.name != expression->name) continue;
    call.diagnostics.error(expression->position, "expression '" + printable(expression->name) +
                                                     "' is already defined at " + at_text(earlier.position) +
                                                     "; define it once");
    return {};
  }
  call.script.meaning.vascular_expressions.push_back(std::move(*expression));
  expression.reset();
  return {};
}

// Emotions may name expressions defined later in the script, so colours are
// resolved once every sentence has been read.
void resolve_emotion_colours(ScriptBuilder& script, DiagnosticList& diagnostics) {
  const auto& expressions = script.meaning.vascular_expressions;
  for (VascularEmotion& emotion : script.meaning.emotions) {
    emotion.colour_keys.clear();
    emotion.colours_resolved = true;
    std::vector<ColourKey> keys{{0.0, {}}};
    for (const EmotionStage& stage : emotion.stages) {
      ColourKey key{stage.end_percent, {}};
      if (!stage.expression.empty()) {
        const auto found = std::find_if(expressions.begin(), expressions.end(),
                                        [&](const VascularExpression& e) { return e.name == stage.expression; });
        if (found == expressions.end()) {
          diagnostics.warning(stage.position, "emotion '" + printable(emotion.name) + "' uses the expression '" +
                                                  printable(stage.expression) +
                                                  "', which this script does not define; its colours stay "
                                                  "unresolved (define it with [expression " +
                                                  printable(stage.expression) + " [mpca REGION intensity X] ...])");
          emotion.colours_resolved = false;
          continue;
        }
        // Rounded to a millionth, far below what 8-bit colour shows, so that
        // 0.4 x 0.9 reads 0.36 rather than 0.36000000000000004.
        for (std::size_t c = 0; c < kColourChannelCount; ++c)
          key.channels[c] = std::round(found->channels[c] * stage.intensity * 1e6) / 1e6;
      }
      keys.push_back(key);
    }
    if (emotion.colours_resolved) emotion.colour_keys = std::move(keys);
  }
}

}  // namespace

void add_vascular_routines(RoutineLibrary& library) {
  library.add({"begin_emotion", {{kTextParameter, "the emotion's name"}}, ValueKind::none, begin_emotion,
               "opens a vascular emotion"});
  library.add({"begin_stage",
               {{kTextParameter, "the stage's name"}, {kNumberParameter, "its duration in percent"}},
               ValueKind::none,
               begin_stage,
               "adds a stage to the emotion"});
  library.add({"stage_expression",
               {{kTextParameter, "the expression's name"}, {kNumberParameter, "its intensity"}},
               ValueKind::none,
               stage_expression,
               "sets the expression the stage ends on"});
  library.add({"end_emotion", {}, ValueKind::none, end_emotion, "closes a vascular emotion"});
  library.add({"begin_vascular_expression", {{kTextParameter, "the expression's name"}}, ValueKind::none,
               begin_vascular_expression, "opens a vascular expression"});
  library.add({"mpca_intensity",
               {{kTextParameter, "the region"}, {kNumberParameter, "its intensity"}},
               ValueKind::none,
               mpca_intensity,
               "sets the colour intensity of one region"});
  library.add({"end_vascular_expression", {}, ValueKind::none, end_vascular_expression,
               "closes a vascular expression"});
  library.add_finish(resolve_emotion_colours);
}

}  // namespace fw::script
