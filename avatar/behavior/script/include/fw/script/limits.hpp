#pragma once
// Every bound the face-script front end puts on what a person gives it, in
// one place so that the README, the error messages and the fuzz target agree.
// Sentences come from users (chat commands, uploaded files) and grammars from
// designers; either may be hostile or broken, so time and memory stay bounded
// whatever the bytes.
#include <cstddef>

namespace fw::script {

// Sentences.
inline constexpr std::size_t kMaxScriptBytes = 1 << 20;   ///< one script (file or command): 1 MiB
inline constexpr std::size_t kMaxTokenBytes = 256;        ///< one word, number or string; comments are exempt
inline constexpr std::size_t kMaxParseStackDepth = 512;   ///< open symbols while parsing: bounds nesting
inline constexpr std::size_t kMaxSentences = 10000;       ///< sentences in one script
inline constexpr std::size_t kMaxErrors = 25;             ///< errors reported before giving up
inline constexpr std::size_t kMaxWarnings = 100;          ///< warnings kept

// Meaning.
inline constexpr std::size_t kMaxKeyframes = 1000;         ///< keyframes in one expression sentence
inline constexpr std::size_t kMaxPlays = 1000;             ///< Animate/Hold statements in one sentence
inline constexpr std::size_t kMaxDisplacements = 1000;     ///< control-point lines in one AU definition
inline constexpr std::size_t kMaxStages = 32;              ///< stages in one vascular emotion
inline constexpr std::size_t kMaxMpcas = 16;               ///< region intensities in one vascular expression
inline constexpr long long kMaxSteps = 10000;              ///< steps of one Animate or Hold
/// Written AU intensity: the paper's scale, on which 2.0 is an action unit at
/// its full strength (its anger writes AU 4 at 2.0), so half of it is the
/// face's weight (AuIntensity::face_intensity).
inline constexpr double kMaxAuIntensity = 2.0;
inline constexpr long long kMaxControlPoint = 9999;        ///< control-point index in an AU definition
inline constexpr double kMaxDisplacement = 1000.0;         ///< |dx|, |dy|, |dz| in an AU definition
inline constexpr std::size_t kMaxShadingBytes = 64;        ///< the shading string of Animate

// Grammars.
inline constexpr std::size_t kMaxGrammarBytes = 256 * 1024;  ///< one grammar file
inline constexpr std::size_t kMaxTerminals = 128;
inline constexpr std::size_t kMaxNonterminals = 256;
inline constexpr std::size_t kMaxProductions = 512;
inline constexpr std::size_t kMaxRhsSymbols = 32;            ///< symbols on the right of one production
inline constexpr std::size_t kMaxSpellingBytes = 32;         ///< one keyword, symbol or comment introducer
inline constexpr std::size_t kMaxCommentIntroducers = 4;
inline constexpr std::size_t kMaxScanStates = 4096;          ///< states of the generated scanner
inline constexpr int kMaxIncludeDepth = 4;                   ///< #Include nesting
inline constexpr std::size_t kMaxGrammarFiles = 16;          ///< files one grammar may include in all
inline constexpr std::size_t kMaxGrammarErrors = 25;

}  // namespace fw::script
