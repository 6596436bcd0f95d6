#include "fw/behavior/room_script.hpp"

#include <algorithm>

#include "fw/behavior/facs_track.hpp"

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"

namespace fw::behavior {
namespace {

std::string count_text(std::size_t n) { return std::to_string(n); }

double play_s(const script::KeyframeAnimation& a) {
  double steps = 0;
  for (const script::Play& p : a.plays) steps += p.steps;
  return steps * AuTrack::kStepS;
}

// The expressions `emotion` names that the script does not define, or "".
std::string undefined_expressions(const script::VascularEmotion& emotion, const script::ScriptMeaning& meaning) {
  std::string missing;
  for (const script::EmotionStage& stage : emotion.stages) {
    if (stage.expression.empty()) continue;
    const bool defined = std::any_of(meaning.vascular_expressions.begin(), meaning.vascular_expressions.end(),
                                     [&](const script::VascularExpression& e) { return e.name == stage.expression; });
    if (!defined && missing.find("'" + stage.expression + "'") == std::string::npos)
      missing += (missing.empty() ? "'" : ", '") + stage.expression + "'";
  }
  return missing;
}

}  // namespace

std::string read_room_script(std::string_view text, RoomScript& out, const model::GenericFace& face) {
  if (text.size() > kMaxRoomScriptBytes)
    return "the script is " + count_text(text.size()) + " bytes; at most " + count_text(kMaxRoomScriptBytes) +
           " are played: shorten it";
  const script::ScriptResult result = script::parse_script(script::default_language(), text);
  for (const script::Diagnostic& d : result.diagnostics)
    if (d.severity == script::Severity::error)
      return "script " + std::to_string(d.position.line) + ":" + std::to_string(d.position.column) + ": " + d.message;
  const script::ScriptMeaning& m = result.meaning;
  if (m.au_definitions.size() > kMaxRoomScriptAuDefinitions)
    return "the script has " + count_text(m.au_definitions.size()) + " AU definitions; at most " +
           count_text(kMaxRoomScriptAuDefinitions) + " are taken at once: send the rest in another script";
  if (m.animations.empty() && m.emotions.empty() && m.au_definitions.empty())
    return "no expression sentence, vascular emotion or AU definition (write e.g. ClearAllFrame BeginKeyFrame 12 2.0 "
           "Animate 5 \"Texture\" end)";
  if (m.animations.size() > 1 || m.emotions.size() > 1)
    return "the script has " + count_text(m.animations.size()) + " expression sentences and " +
           count_text(m.emotions.size()) + " vascular emotions; a room plays at most one of each: send one at a time";
  if (m.vascular_expressions.size() > kMaxRoomScriptVascularExpressions)
    return "the script defines " + count_text(m.vascular_expressions.size()) + " vascular expressions; at most " +
           count_text(kMaxRoomScriptVascularExpressions) + " are read: define only those the emotion uses";
  RoomScript read;
  if (!m.animations.empty()) {
    const script::KeyframeAnimation& a = m.animations.front();
    if (a.keyframes.size() > kMaxRoomScriptKeyframes)
      return "the sentence has " + count_text(a.keyframes.size()) + " keyframes; at most " +
             count_text(kMaxRoomScriptKeyframes) + " are played: send the rest as another sentence";
    if (const double s = play_s(a); s > kMaxRoomScriptPlayS)
      return "the sentence plays " + std::to_string(static_cast<long long>(s)) + " s (0.1 s a step); at most " +
             std::to_string(static_cast<int>(kMaxRoomScriptPlayS)) + " s are played: use fewer steps";
    read.animation = a;
  }
  if (!m.emotions.empty()) {
    const script::VascularEmotion& e = m.emotions.front();
    if (!e.colours_resolved)
      return "the emotion '" + e.name + "' uses " + undefined_expressions(e, m) +
             ", not defined in the script: define each [expression NAME ...] it names";
    read.emotion = e;
  }
  for (const script::AuDefinition& d : m.au_definitions)
    if (std::string error = read_unit_definition(d, face, read.units.emplace_back()); !error.empty())
      return "script " + std::to_string(d.position.line) + ":" + std::to_string(d.position.column) + ": " + error;
  out = std::move(read);
  return {};
}

}  // namespace fw::behavior
