#pragma once
// The state the semantic routines share while a script is parsed: the
// meaning so far and the one sentence under construction. A sentence with an
// error is rolled back whole, so the meaning only ever holds sentences that
// were right.
#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "fw/script/script_meaning.hpp"

namespace fw::script {

struct ScriptBuilder {
  ScriptMeaning meaning;

  // Opened and closed by the routines of each language; at most one is open
  // in a well-bound grammar.
  std::optional<KeyframeAnimation> animation;
  std::optional<AuDefinition> au_definition;
  std::optional<VascularEmotion> emotion;
  std::optional<VascularExpression> vascular_expression;

  /// Forgets anything left open and remembers how much meaning there is.
  void begin_sentence();
  /// Drops whatever the current sentence added to `meaning` and left open.
  void discard_sentence();
  /// What the sentence left open, e.g. "an expression sentence (no routine
  /// closed it: bind end_animation ...)"; empty when nothing is open.
  std::string unfinished() const;

 private:
  std::array<std::size_t, 4> sizes_{};
};

}  // namespace fw::script
