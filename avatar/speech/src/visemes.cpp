#include "fw/speech/visemes.hpp"

#include <cctype>
#include <string>

#include "fw/codec/face_params.hpp"

namespace fw::speech {
namespace {

// The viseme of one espeak-ng base symbol; case matters ('W' is the vowel
// of German "Hölle", 'w' the English glide).
std::optional<Viseme> symbol_viseme(char symbol) {
  switch (symbol) {
    case 'p': case 'b': case 'm': case 'B': return Viseme::bilabial;
    case 'f': case 'v': case 'F': case 'M': return Viseme::labiodental;
    case 'T': case 'D': return Viseme::dental;
    case 't': case 'd': case 'n': case 'l': case 's': case 'z': case 'L': return Viseme::alveolar;
    case 'S': case 'Z': return Viseme::postalveolar;
    case 'k': case 'g': case 'N': case 'x': case 'X': case 'q': case 'G': case 'Q': return Viseme::velar;
    case 'h': case '?': return Viseme::glottal;
    case 'r': case 'R': return Viseme::rhotic;
    case 'a': case 'A': case 'V': case '&': case '6': return Viseme::open_vowel;
    case 'e': case 'E': case '@': case '3': return Viseme::mid_vowel;
    case 'i': case 'I': case 'j': case 'C': case 'J': case 'c': return Viseme::close_front_vowel;
    case 'o': case 'O': case '0': case '2': case '9': case 'W': case 'Y': return Viseme::open_rounded_vowel;
    case 'u': case 'U': case 'y': case 'w': case 'H': return Viseme::close_rounded_vowel;
    default: return std::nullopt;
  }
}

bool is_vowel(Viseme v) { return v >= Viseme::open_vowel && v != Viseme::count; }

// A mnemonic's base symbols: its first character (which may be a digit,
// '@' or '&'), then the letters, '@' and '&' after it. Digits after the
// first character number variants ("I2", "R2"); ':' '#' '-' '~' '^' mark
// length, variants, nasality, palatals.
std::string base_symbols(std::string_view name) {
  std::string symbols(1, name.front());
  for (char c : name.substr(1))
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '@' || c == '&') symbols += c;
  return symbols;
}

// Affricates are one phoneme: their closure, then their release.
std::optional<PhonemeVisemes> affricate(std::string_view symbols) {
  if (symbols == "tS" || symbols == "dZ") return PhonemeVisemes{Viseme::postalveolar, Viseme::postalveolar};
  if (symbols == "ts" || symbols == "dz") return PhonemeVisemes{Viseme::alveolar, Viseme::alveolar};
  if (symbols == "pF" || symbols == "pf") return PhonemeVisemes{Viseme::bilabial, Viseme::labiodental};
  return std::nullopt;
}

AuTargets targets(std::initializer_list<std::pair<int, float>> units) {
  codec::FaceParams params;
  for (const auto& [au, intensity] : units) params.set_au(au, intensity);
  return params.au;
}

}  // namespace

std::optional<PhonemeVisemes> visemes_of(std::string_view espeak_phoneme) {
  if (espeak_phoneme.empty()) return std::nullopt;
  if (espeak_phoneme.front() == '_') return PhonemeVisemes{Viseme::rest, Viseme::rest};
  const std::string symbols = base_symbols(espeak_phoneme);
  if (auto both = affricate(symbols)) return both;
  const auto first = symbol_viseme(symbols.front());
  if (!first) return std::nullopt;
  PhonemeVisemes visemes{*first, *first};
  // A diphthong ends on its last vowel ("aI", "oU", "i@3": ends on @).
  if (is_vowel(*first)) {
    for (char c : std::string_view(symbols).substr(1)) {
      const auto next = symbol_viseme(c);
      if (next && is_vowel(*next)) visemes.second = *next;
    }
  }
  return visemes;
}

const AuTargets& viseme_targets(Viseme viseme) {
  // Intensities chosen on the generic face (avatar/model's action-unit
  // basis, where 0.1 unit is 6.3 mm) for the gap between the inner lips: an
  // open vowel parts them by 11 mm, a mid vowel 8, a close one 6, the
  // tongue consonants 2-3 (the jaw nearly closed), near a speaker's lips at
  // a conversational level (10-15 mm for /a/); the resting face has a 1 mm
  // slit. AU 25 and 26 open the mouth; 24 presses the lips (bilabial
  // closure; its morph, made by the physics face, brings them just into
  // contact, so 23 and 17 press on past it: the lips' linear sum overlaps
  // by 0.85 mm, which holds the closure against the jaw a neighbouring
  // vowel leaves open); 23 and a little 17 narrow and push them forward
  // (rounding: the face has no AU 18 pucker); 20 and lightly 12 spread them
  // for /i/; 10 raises the upper lip off the teeth for f and v, 17 lifts the
  // lower one to them. tests/speech measures these gaps on the face.
  static const std::array<AuTargets, kVisemeCount> table = {
      targets({}),                                                  // rest
      targets({{24, 1.0f}, {23, 0.6f}, {17, 0.3f}}),                // bilabial
      targets({{10, 0.3f}, {17, 0.35f}}),                           // labiodental
      targets({{25, 0.35f}, {26, 0.06f}}),                          // dental
      targets({{25, 0.3f}, {26, 0.04f}, {20, 0.1f}}),               // alveolar
      targets({{23, 0.4f}, {25, 0.35f}, {26, 0.08f}, {17, 0.1f}}),  // postalveolar
      targets({{25, 0.3f}, {26, 0.05f}}),                           // velar
      targets({{25, 0.45f}, {26, 0.2f}}),                           // glottal
      targets({{23, 0.3f}, {25, 0.35f}, {26, 0.06f}}),              // rhotic
      targets({{25, 0.7f}, {26, 0.5f}}),                            // open vowel
      targets({{25, 0.6f}, {26, 0.34f}, {20, 0.1f}}),               // mid vowel
      targets({{25, 0.7f}, {26, 0.24f}, {20, 0.2f}, {12, 0.1f}}),   // close front vowel
      targets({{23, 0.4f}, {25, 0.55f}, {26, 0.3f}, {17, 0.1f}}),   // open rounded vowel
      targets({{23, 0.5f}, {25, 0.6f}, {26, 0.24f}, {17, 0.1f}}),   // close rounded vowel
  };
  return table[static_cast<std::size_t>(viseme)];
}

}  // namespace fw::speech
