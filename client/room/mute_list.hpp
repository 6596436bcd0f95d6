#pragma once
// Whom the person muted for themselves (`join --mute NAME`, PROTOCOL.md
// 6.3): display names whose chat lines the client neither prints nor keeps,
// and whose faces it draws still and neutral. Only this client filters; the
// server sends everything and the muted person is not told. A name, not an
// avatar id: ids change when someone reconnects, and the name is what the
// person knows. Everyone wearing a muted name is muted, the viewer's own
// avatar never. No socket and no clock: RoomState asks it, under its lock.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"

namespace fw::client {

class MuteList {
 public:
  MuteList() = default;
  explicit MuteList(const std::vector<std::string>& names) : names_(names.begin(), names.end()) {}

  bool empty() const { return names_.empty(); }
  const std::set<std::string>& names() const { return names_; }
  /// Whether avatar `id` named `name` is muted for the viewer `you`.
  bool mutes(std::uint32_t id, const std::string& name, std::uint32_t you) const {
    return id != 0 && id != you && names_.count(name) > 0;
  }

  /// Counts a line of `name` that was not shown.
  void line_hidden(const std::string& name) { ++hidden_lines_[name]; }
  /// Lines not shown, by name (only names with at least one).
  const std::map<std::string, int>& hidden_lines() const { return hidden_lines_; }

  /// What the person reads on joining, one line per muted name: whom it
  /// mutes among `avatars`, and that everyone sharing the name is muted.
  std::vector<std::string> notices(const std::vector<codec::AvatarInfo>& avatars, std::uint32_t you) const;

  /// A muted face: at rest, no action units, eyes and head straight ahead,
  /// lids open, no blush or pallor.
  static codec::FaceParams still_face() { return codec::FaceParams{}; }

 private:
  std::set<std::string> names_;
  std::map<std::string, int> hidden_lines_;
};

}  // namespace fw::client
