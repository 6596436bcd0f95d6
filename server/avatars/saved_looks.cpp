#include "saved_looks.hpp"

#include <charconv>

#include "display_name.hpp"

namespace fw::server {

namespace {

constexpr std::string_view kHeader = "facewire looks 1\n";

/// The number at `at` in `bytes` up to `end`; false if there is none.
bool read_count(std::string_view bytes, std::size_t& at, char end, std::size_t& count) {
  const char* first = bytes.data() + at;
  const char* last = bytes.data() + bytes.size();
  const auto [stop, ec] = std::from_chars(first, last, count);
  if (ec != std::errc{} || stop == last || *stop != end) return false;
  at = static_cast<std::size_t>(stop - bytes.data()) + 1;
  return true;
}

}  // namespace

std::string normalize_look_name(std::string_view name, std::string& normalized) {
  if (name.empty()) return "a look needs a name: 1 to " + std::to_string(kMaxLookNameBytes) + " bytes";
  const auto too_long = [](std::size_t bytes) {
    return "the look's name is " + std::to_string(bytes) + " bytes; at most " + std::to_string(kMaxLookNameBytes) +
           " (32 letters of the Latin alphabet): choose a shorter one";
  };
  // The rules of display names, in words about a look.
  if (std::string why = normalize_display_name(name, normalized); !why.empty()) {
    if (why.starts_with("a display name needs")) return "a look's name needs at least one visible character";
    if (why.starts_with("a display name is")) return too_long(name.size());
    return why;
  }
  if (normalized.size() > kMaxLookNameBytes) return too_long(normalized.size());
  return {};
}

std::string encode_looks(const std::vector<SavedLook>& looks) {
  std::string out(kHeader);
  for (const SavedLook& look : looks) {
    out += std::to_string(look.name.size()) + " " + std::to_string(look.script.size()) + "\n";
    out += look.name;
    out += look.script;
    out += "\n";
  }
  return out;
}

bool decode_looks(std::string_view bytes, std::vector<SavedLook>& looks) {
  looks.clear();
  if (!bytes.starts_with(kHeader)) return false;
  std::size_t at = kHeader.size();
  std::vector<SavedLook> read;
  while (at < bytes.size()) {
    std::size_t name_bytes = 0, script_bytes = 0;
    if (!read_count(bytes, at, ' ', name_bytes) || !read_count(bytes, at, '\n', script_bytes)) return false;
    if (name_bytes == 0 || name_bytes > kMaxLookNameBytes || script_bytes > kMaxLookScriptBytes ||
        bytes.size() - at < name_bytes + script_bytes + 1 || bytes[at + name_bytes + script_bytes] != '\n' ||
        read.size() == kMaxLooksPerAvatar)
      return false;
    read.push_back(
        {std::string(bytes.substr(at, name_bytes)), std::string(bytes.substr(at + name_bytes, script_bytes))});
    at += name_bytes + script_bytes + 1;
  }
  looks = std::move(read);
  return true;
}

}  // namespace fw::server
