#pragma once
// A simple appraisal of a chat line: laughter, emoticons, question and
// exclamation marks and a small word list nudge the writer's emotion.
#include <string_view>

#include "fw/behavior/emotion_space.hpp"

namespace fw::behavior {

/// How much `text` moves its writer in expression space (each coordinate
/// 0 .. 1; all zero for a line that says nothing emotional). Case is
/// ignored; only the first 4096 bytes are read.
EmotionPoint appraise_chat(std::string_view text);

/// Whether `text` says its writer is embarrassed (an apology for a slip,
/// "awkward", a flushed face): a cause of blushing. Same reading as above.
bool embarrassing_chat(std::string_view text);

}  // namespace fw::behavior
