#include "display_name.hpp"

#include <cstdio>

#include <unicode/normalizer2.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>

#include "fw/codec/messages.hpp"
#include "visible_text.hpp"

namespace fw::server {
namespace {

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
    // Emoji keep the variation selectors and joiners they are written with
    // ("❤️", "👩‍💻"); acts_unseen() knows them.
    if (acts_unseen(static_cast<char32_t>(before), static_cast<char32_t>(c), static_cast<char32_t>(next)))
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
