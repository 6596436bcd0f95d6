#pragma once
// Visemes: the mouth shapes a viewer can tell apart, and the action-unit
// targets that make them on a facewire face.
//
// The consonant classes are those a viewer confuses with each other
// (Fisher, "Confusions among visually perceived consonants", J. Speech and
// Hearing Research 11, 1968) as the MPEG-4 face animation standard tabulates
// them (ISO/IEC 14496-2, annex C, visemes 1-9: p b m / f v / T D / t d /
// k g / tS dZ S / s z / n l / r); t d, s z and n l look alike on the lips and
// share one class here. The vowels are its visemes 10-14 (A: e I Q U) by
// openness and rounding, with the open rounded back vowels (Q, O) apart from
// the close ones (u, U) as there.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "fw/speech/au_targets.hpp"

namespace fw::speech {

enum class Viseme : std::uint8_t {
  rest,                 ///< silence: the face's neutral mouth
  bilabial,             ///< p b m (and es B): lips closed
  labiodental,          ///< f v: lower lip under the upper teeth
  dental,               ///< T D (th): tongue between the teeth, lips a little apart
  alveolar,             ///< t d n l s z: lips a little apart, jaw nearly closed
  postalveolar,         ///< S Z tS dZ: lips pushed forward and drawn in
  velar,                ///< k g N x: jaw a little open, lips free
  glottal,              ///< h and the glottal stop: the mouth of the neighbouring vowel
  rhotic,               ///< r R: lips slightly rounded
  open_vowel,           ///< a A V: jaw wide open
  mid_vowel,            ///< e E @ 3: jaw half open
  close_front_vowel,    ///< i I, and j: lips spread, jaw nearly closed
  open_rounded_vowel,   ///< o O 0, front rounded 2 9 W Y: rounded, jaw half open
  close_rounded_vowel,  ///< u U y, and w: rounded and narrow
  count
};
inline constexpr std::size_t kVisemeCount = static_cast<std::size_t>(Viseme::count);

/// The visemes one phoneme moves through: a diphthong ("aI") glides from
/// its first to its second; any other phoneme has `second == first`.
struct PhonemeVisemes {
  Viseme first = Viseme::rest;
  Viseme second = Viseme::rest;
};

/// The visemes of an espeak-ng phoneme mnemonic, for the voices of en, de,
/// fr, es and others (espeak-ng's docs/phonemes.md names them: a base symbol
/// then modifiers such as ':' long, '#' and digits variants, '~' nasal).
/// Pauses ('_', '_:') are rest. Nothing for what has no mouth shape of its
/// own: a language switch "(en)", stress or tone marks.
std::optional<PhonemeVisemes> visemes_of(std::string_view espeak_phoneme);

/// The action-unit targets of `viseme` at full articulation: only the jaw
/// and lip units (10, 12, 14, 17, 20, 23, 24, 25, 26, 27), on both sides.
const AuTargets& viseme_targets(Viseme viseme);

}  // namespace fw::speech
