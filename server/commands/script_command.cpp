#include "script_command.hpp"

#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "fw/model/file_io.hpp"
#include "fw/script/grammar_sources.hpp"
#include "fw/script/limits.hpp"
#include "fw/script/parser.hpp"
#include "fw/script/region_names.hpp"
#include "fw/script/standard_routines.hpp"

namespace fw::server {
namespace {

using nlohmann::ordered_json;

struct ScriptArgs {
  std::string file;
  std::string grammar;
};

ordered_json line_of(const script::SourcePosition& p) { return p.line; }

ordered_json plays_json(const std::vector<script::Play>& plays) {
  ordered_json out = ordered_json::array();
  for (const script::Play& play : plays) {
    ordered_json p;
    p["line"] = line_of(play.position);
    p["kind"] = play.kind == script::PlayKind::animate ? "animate" : "hold";
    p["steps"] = play.steps;
    if (play.kind == script::PlayKind::animate) p["shading"] = play.shading;
    p["after_keyframes"] = play.keyframe_count;
    out.push_back(std::move(p));
  }
  return out;
}

ordered_json channels_json(const script::ColourChannels& channels) {
  ordered_json out = ordered_json::object();
  for (std::size_t c = 0; c < channels.size(); ++c) out[std::string(script::colour_channel_name(c))] = channels[c];
  return out;
}

ordered_json animations_json(const std::vector<script::KeyframeAnimation>& animations) {
  ordered_json out = ordered_json::array();
  for (const script::KeyframeAnimation& a : animations) {
    ordered_json keyframes = ordered_json::array();
    for (const script::Keyframe& k : a.keyframes) {
      ordered_json aus = ordered_json::array();
      for (const script::AuIntensity& au : k.aus)
        aus.push_back({{"au", au.au}, {"intensity", au.intensity}, {"face_intensity", au.face_intensity},
                       {"carried", au.carried}});
      keyframes.push_back({{"line", line_of(k.position)}, {"aus", std::move(aus)}});
    }
    out.push_back({{"line", line_of(a.position)},
                   {"start", a.clear_frames ? "neutral" : "current"},
                   {"keyframes", std::move(keyframes)},
                   {"plays", plays_json(a.plays)}});
  }
  return out;
}

ordered_json au_definitions_json(const std::vector<script::AuDefinition>& definitions) {
  ordered_json out = ordered_json::array();
  for (const script::AuDefinition& d : definitions) {
    ordered_json points = ordered_json::array();
    for (const script::ControlPointDisplacement& p : d.displacements)
      points.push_back({{"region", p.region},
                        {"face_regions", p.face_regions},
                        {"point", p.point},
                        {"displacement", p.displacement}});
    out.push_back({{"line", line_of(d.position)},
                   {"au", d.au},
                   {"carried", d.carried},
                   {"displacements", std::move(points)},
                   {"preview_from", d.preview_from_neutral ? "neutral" : "current"},
                   {"previews", plays_json(d.previews)}});
  }
  return out;
}

ordered_json vascular_expressions_json(const std::vector<script::VascularExpression>& expressions) {
  ordered_json out = ordered_json::array();
  for (const script::VascularExpression& e : expressions) {
    ordered_json regions = ordered_json::array();
    for (const script::RegionIntensity& r : e.regions)
      regions.push_back({{"region", r.region}, {"channels", r.channels}, {"intensity", r.intensity}});
    out.push_back({{"line", line_of(e.position)},
                   {"name", e.name},
                   {"regions", std::move(regions)},
                   {"channels", channels_json(e.channels)}});
  }
  return out;
}

ordered_json stages_json(const std::vector<script::EmotionStage>& stages) {
  ordered_json out = ordered_json::array();
  for (const script::EmotionStage& s : stages) {
    ordered_json stage{{"name", s.name},
                       {"duration_percent", s.duration_percent},
                       {"start_percent", s.start_percent},
                       {"end_percent", s.end_percent}};
    if (!s.expression.empty()) {
      stage["expression"] = s.expression;
      stage["intensity"] = s.intensity;
    }
    out.push_back(std::move(stage));
  }
  return out;
}

ordered_json emotion_json(const script::VascularEmotion& e) {
  ordered_json envelope = ordered_json::array();
  for (const script::EnvelopeKey& k : e.envelope)
    envelope.push_back({{"at_percent", k.at_percent}, {"intensity", k.intensity}});
  ordered_json emotion{{"line", line_of(e.position)},
                       {"name", e.name},
                       {"stages", stages_json(e.stages)},
                       {"envelope", std::move(envelope)},
                       {"colours_resolved", e.colours_resolved}};
  if (e.colours_resolved) {
    ordered_json keys = ordered_json::array();
    for (const script::ColourKey& k : e.colour_keys)
      keys.push_back({{"at_percent", k.at_percent}, {"channels", channels_json(k.channels)}});
    emotion["colour_keys"] = std::move(keys);
  }
  return emotion;
}

ordered_json meaning_json(const std::string& file, const script::ScriptResult& result) {
  const script::ScriptMeaning& m = result.meaning;
  ordered_json out;
  out["file"] = file;
  out["sentences"] = result.sentences;
  out["animations"] = animations_json(m.animations);
  out["au_definitions"] = au_definitions_json(m.au_definitions);
  out["vascular_expressions"] = vascular_expressions_json(m.vascular_expressions);
  ordered_json emotions = ordered_json::array();
  for (const script::VascularEmotion& e : m.emotions) emotions.push_back(emotion_json(e));
  out["emotions"] = std::move(emotions);
  ordered_json warnings = ordered_json::array();
  for (const script::Diagnostic& d : result.diagnostics)
    if (d.severity == script::Severity::warning) warnings.push_back(script::format_diagnostic(file, d));
  out["warnings"] = std::move(warnings);
  return out;
}

int run_script(const ScriptArgs& args) {
  const auto fail = [](const std::string& message) {
    std::cerr << "facewire-server script: " << message << "\n";
    return 2;
  };

  std::optional<script::Language> loaded;
  const script::Language* language = &script::default_language();
  if (!args.grammar.empty()) {
    std::string error;
    const auto source = script::read_grammar_file(args.grammar, error);
    if (!source) return fail(error);
    std::vector<script::GrammarError> errors;
    loaded = script::load_language(*source, script::file_resolver(), script::standard_routines(), errors);
    if (!loaded) {
      for (const script::GrammarError& e : errors) std::cerr << script::format_grammar_error(e) << "\n";
      std::cerr << "facewire-server script: the grammar " << args.grammar
                << " cannot be used; fix the lines above (the format is in avatar/behavior/script/README.md)\n";
      return 2;
    }
    language = &*loaded;
  }

  std::vector<std::uint8_t> bytes;
  std::string error;
  if (!model::read_file(args.file, script::kMaxScriptBytes, bytes, error)) return fail(error);
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const script::ScriptResult result = script::parse_script(*language, text);

  for (const script::Diagnostic& d : result.diagnostics) std::cerr << script::format_diagnostic(args.file, d) << "\n";
  if (!result.ok()) return 2;
  // Names and strings come from the script and may hold any bytes; invalid
  // UTF-8 is replaced rather than thrown over.
  std::cout << meaning_json(args.file, result).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

}  // namespace

void add_script_command(CLI::App& app) {
  auto args = std::make_shared<ScriptArgs>();
  CLI::App* cmd = app.add_subcommand(
      "script", "Parse a file of face-script sentences (expressions, AU definitions, vascular emotions) into JSON");
  cmd->add_option("file", args->file, "the script (at most 1 MiB)")->required();
  cmd->add_option("--grammar", args->grammar,
                  "a grammar file to read the script with (default: the shipped facewire.grammar)");
  cmd->callback([args] { std::exit(run_script(*args)); });
}

}  // namespace fw::server
