#pragma once
// The characters of a word (an identifier or a keyword), for the scanner
// and the grammar reader alike: ASCII only, whatever the locale.

namespace fw::script {

inline bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
inline bool is_word_char(char c) { return is_word_start(c) || (c >= '0' && c <= '9'); }

}  // namespace fw::script
