#include "visible_text.hpp"

#include <unicode/normalizer2.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>

namespace fw::server {
namespace {

/// Whether `c` would act on the text around it without a glyph of its own,
/// or is no character at all, whatever its neighbours.
bool invisible_or_control(UChar32 c) {
  switch (u_charType(c)) {
    case U_CONTROL_CHAR:         // C0, C1
    case U_FORMAT_CHAR:          // bidi embeddings, overrides and isolates, zero-width space and joiners, BOM
    case U_LINE_SEPARATOR:
    case U_PARAGRAPH_SEPARATOR:
    case U_SURROGATE:
    case U_PRIVATE_USE_CHAR:
    case U_UNASSIGNED:           // noncharacters included
      return true;
    default:
      break;
  }
  // Blank-looking characters of other categories (the Hangul fillers, the
  // combining grapheme joiner) are default-ignorable: shown as nothing.
  return u_hasBinaryProperty(c, UCHAR_DEFAULT_IGNORABLE_CODE_POINT);
}

}  // namespace

bool acts_unseen(char32_t before, char32_t c, char32_t after, bool script_joiners) {
  const auto b = static_cast<UChar32>(before);
  const auto u = static_cast<UChar32>(c);
  const auto a = static_cast<UChar32>(after);
  if (u >= 0xFE00 && u <= 0xFE0F && b != 0 && !invisible_or_control(b)) return false;
  if (u == 0x200D && u_hasBinaryProperty(b, UCHAR_EXTENDED_PICTOGRAPHIC) &&
      u_hasBinaryProperty(a, UCHAR_EXTENDED_PICTOGRAPHIC))
    return false;
  if (script_joiners && (u == 0x200C || u == 0x200D) && u_isalpha(b) && u_isalpha(a)) return false;
  return invisible_or_control(u);
}

std::size_t clean_chat_text(std::string_view text, std::string& cleaned, std::size_t max_bytes) {
  cleaned.clear();
  const icu::UnicodeString in =
      icu::UnicodeString::fromUTF8(icu::StringPiece(text.data(), static_cast<int32_t>(text.size())));
  UErrorCode status = U_ZERO_ERROR;
  const icu::Normalizer2* nfc = icu::Normalizer2::getNFCInstance(status);
  if (U_FAILURE(status)) return 0;
  const icu::UnicodeString nfc_text = nfc->normalize(in, status);
  if (U_FAILURE(status)) return 0;
  icu::UnicodeString out;
  std::size_t left_out = 0;
  UChar32 before = 0;
  for (int32_t i = 0; i < nfc_text.length(); i = nfc_text.moveIndex32(i, 1)) {
    const UChar32 c = nfc_text.char32At(i);
    const int32_t next_at = nfc_text.moveIndex32(i, 1);
    const UChar32 after = next_at < nfc_text.length() ? nfc_text.char32At(next_at) : 0;
    // Judged against the text as written, so that removing one character
    // does not make its neighbour's joiner look legitimate.
    if (acts_unseen(static_cast<char32_t>(before), static_cast<char32_t>(c), static_cast<char32_t>(after), true)) {
      ++left_out;
    } else {
      out.append(c);
    }
    before = c;
  }
  out.toUTF8String(cleaned);
  if (cleaned.size() > max_bytes) {
    std::size_t end = max_bytes;
    while (end > 0 && (static_cast<unsigned char>(cleaned[end]) & 0xC0) == 0x80) --end;  // not mid-character
    cleaned.resize(end);
  }
  return left_out;
}

}  // namespace fw::server
