#include "display_name.hpp"

#include <cstdio>

#include <unicode/normalizer2.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>

#include "fw/codec/messages.hpp"

namespace fw::server {
namespace {

/// Whether `c` would act on the text around it without a glyph of its own,
/// or is no character at all.
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

std::string hex(UChar32 c) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(c));
  return text;
}

}  // namespace

std::string normalize_display_name(std::string_view name, std::string& normalized) {
  const icu::UnicodeString text =
      icu::UnicodeString::fromUTF8(icu::StringPiece(name.data(), static_cast<int32_t>(name.size())));
  UErrorCode status = U_ZERO_ERROR;
  const icu::Normalizer2* nfc = icu::Normalizer2::getNFCInstance(status);
  if (U_FAILURE(status)) return "names cannot be checked on this server (no Unicode data)";
  const icu::UnicodeString nfc_text = nfc->normalize(text, status);
  if (U_FAILURE(status)) return "the name is not valid UTF-8";
  bool visible = false;
  UChar32 previous = 0;
  for (int32_t i = 0; i < nfc_text.length(); i = nfc_text.moveIndex32(i, 1)) {
    const UChar32 c = nfc_text.char32At(i);
    const int32_t after = nfc_text.moveIndex32(i, 1);
    const UChar32 next = after < nfc_text.length() ? nfc_text.char32At(after) : 0;
    const UChar32 before = previous;
    previous = c;
    // Emoji are written with two invisible characters: a variation
    // selector after a visible character picks its style (as in "❤️"), and
    // a zero-width joiner between two pictographs makes one ("👩‍💻").
    if (c >= 0xFE00 && c <= 0xFE0F && before != 0 && !invisible_or_control(before)) continue;
    if (c == 0x200D && u_hasBinaryProperty(before, UCHAR_EXTENDED_PICTOGRAPHIC) &&
        u_hasBinaryProperty(next, UCHAR_EXTENDED_PICTOGRAPHIC))
      continue;
    if (invisible_or_control(c))
      return "the name holds an invisible or control character (" + hex(c) +
             "): use letters, digits, punctuation, spaces and emoji";
    if (!u_isUWhiteSpace(c)) visible = true;
  }
  if (!visible) return "a display name needs at least one visible character";
  normalized.clear();
  nfc_text.toUTF8String(normalized);
  if (normalized.empty() || normalized.size() > codec::kMaxDisplayNameBytes)
    return "a display name is 1 to " + std::to_string(codec::kMaxDisplayNameBytes) + " bytes of UTF-8";
  return {};
}

}  // namespace fw::server
