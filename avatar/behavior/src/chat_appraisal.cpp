#include "fw/behavior/chat_appraisal.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace fw::behavior {
namespace {

struct Cue {
  std::string_view text;
  Primary primary;
  float weight;
  bool word;  ///< must stand alone (not inside another word)
};

// Emoticons and laughter first, then words. Weights: a cue alone gives a
// visible but moderate expression; several add up.
constexpr Cue kCues[] = {
    {":)", Primary::joy, 0.4f, false},   {":-)", Primary::joy, 0.4f, false},  {":d", Primary::joy, 0.55f, false},
    {"haha", Primary::joy, 0.5f, false}, {"hehe", Primary::joy, 0.4f, false}, {"lol", Primary::joy, 0.45f, true},
    {":(", Primary::sadness, 0.45f, false}, {":-(", Primary::sadness, 0.45f, false}, {":'(", Primary::sadness, 0.6f, false},
    {">:(", Primary::anger, 0.5f, false}, {":o", Primary::surprise, 0.5f, false},  {"o_o", Primary::surprise, 0.4f, false},
    {"great", Primary::joy, 0.3f, true}, {"love", Primary::joy, 0.35f, true},    {"thanks", Primary::joy, 0.25f, true},
    {"nice", Primary::joy, 0.25f, true}, {"happy", Primary::joy, 0.35f, true},   {"sad", Primary::sadness, 0.35f, true},
    {"sorry", Primary::sadness, 0.25f, true}, {"miss", Primary::sadness, 0.2f, true}, {"angry", Primary::anger, 0.4f, true},
    {"hate", Primary::anger, 0.4f, true}, {"damn", Primary::anger, 0.3f, true},  {"scared", Primary::fear, 0.4f, true},
    {"afraid", Primary::fear, 0.4f, true}, {"help", Primary::fear, 0.25f, true}, {"wow", Primary::surprise, 0.4f, true},
    {"what", Primary::surprise, 0.1f, true}, {"really", Primary::surprise, 0.2f, true}, {"omg", Primary::surprise, 0.45f, true},
    {"yuck", Primary::disgust, 0.45f, true}, {"gross", Primary::disgust, 0.4f, true}, {"ew", Primary::disgust, 0.35f, true},
};

// What a writer says when embarrassed at their own slip or at attention
// (apologies for a blunder, "awkward", the flushed-face emoji): the social
// predicaments that bring on a blush (Leary et al. 1992, "Social blushing").
struct EmbarrassmentCue {
  std::string_view text;
  bool word;
};
constexpr EmbarrassmentCue kEmbarrassmentCues[] = {
    {"oops", true},  {"whoops", true},    {"my bad", true}, {"embarrass", false}, {"blush", false},
    {"awkward", true}, {":$", false}, {"\xF0\x9F\x98\xB3", false} /* flushed face */,
    {"\xF0\x9F\x99\x88", false} /* see-no-evil monkey */,
};

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '\''; }

// The first 4096 bytes of `text`, lower-cased (ASCII; other bytes as they are).
std::string lowered(std::string_view text) {
  std::string lower(text.substr(0, std::min<std::size_t>(text.size(), 4096)));
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

// Whether `lower` holds `cue`, standing alone when `word`.
bool has_cue(const std::string& lower, std::string_view cue, bool word) {
  for (std::size_t at = lower.find(cue); at != std::string::npos; at = lower.find(cue, at + 1)) {
    const bool alone = at == 0 || !word_char(lower[at - 1]);
    const std::size_t end = at + cue.size();
    const bool alone_after = end >= lower.size() || !word_char(lower[end]);
    if (!word || (alone && alone_after)) return true;
  }
  return false;
}

}  // namespace

bool embarrassing_chat(std::string_view text) {
  const std::string lower = lowered(text);
  return std::any_of(std::begin(kEmbarrassmentCues), std::end(kEmbarrassmentCues),
                     [&](const EmbarrassmentCue& cue) { return has_cue(lower, cue.text, cue.word); });
}

EmotionPoint appraise_chat(std::string_view text) {
  const std::string lower = lowered(text);
  EmotionPoint delta{};
  auto add = [&](Primary p, float w) { delta[static_cast<std::size_t>(p)] += w; };
  for (const Cue& cue : kCues)
    if (has_cue(lower, cue.text, cue.word)) add(cue.primary, cue.weight);  // a cue counts once per line
  const auto marks = [&](char m) { return static_cast<float>(std::count(lower.begin(), lower.end(), m)); };
  // Exclamations raise arousal (surprise), questions a little curiosity.
  add(Primary::surprise, 0.12f * std::min(3.0f, marks('!')) + 0.06f * std::min(2.0f, marks('?')));
  // Exclamations amplify whatever else the line says.
  if (marks('!') > 0)
    for (std::size_t i = 0; i < kPrimaryCount; ++i)
      if (i != static_cast<std::size_t>(Primary::surprise)) delta[i] *= 1.3f;
  return clamp_to_cube(delta);
}

}  // namespace fw::behavior
