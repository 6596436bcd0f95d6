// Fuzzes the face-script front end. Input without a "%%" line is a script
// in the default language; input with one is a grammar, then a script in
// that grammar's language. Whatever the bytes: a language or grammar errors,
// a meaning or diagnostics with real positions, never a crash, hang or leak.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/limits.hpp"
#include "fw/script/parser.hpp"
#include "fw/script/standard_routines.hpp"

namespace {

void check(const fw::script::ScriptResult& result) {
  bool errors = false;
  for (const fw::script::Diagnostic& d : result.diagnostics) {
    if (d.position.line < 1 || d.position.column < 1 || d.message.empty()) std::abort();
    errors |= d.severity == fw::script::Severity::error;
  }
  if (result.ok() == errors) std::abort();
  if (result.sentences > fw::script::kMaxSentences) std::abort();
  for (const auto& animation : result.meaning.animations) {
    if (animation.keyframes.size() > fw::script::kMaxKeyframes) std::abort();
    for (const auto& keyframe : animation.keyframes)
      for (const auto& au : keyframe.aus)
        if (!(au.face_intensity >= 0 && au.face_intensity <= 1)) std::abort();
  }
  for (const auto& emotion : result.meaning.emotions)
    if (emotion.stages.empty() || emotion.stages.back().end_percent < 99.999) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find("\n%%\n");
  if (split == std::string_view::npos) {
    check(fw::script::parse_script(fw::script::default_language(), input));
    return 0;
  }
  std::vector<fw::script::GrammarError> errors;
  const auto language = fw::script::load_language({"fuzz.grammar", std::string(input.substr(0, split))},
                                                  fw::script::builtin_resolver(), fw::script::standard_routines(),
                                                  errors);
  if (language.has_value() == !errors.empty()) std::abort();  // exactly one of: a language, or reasons
  for (const auto& e : errors)
    if (e.message.empty()) std::abort();
  if (language) check(fw::script::parse_script(*language, input.substr(split + 4)));
  return 0;
}
