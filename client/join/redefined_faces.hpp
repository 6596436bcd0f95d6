#pragma once
// Each avatar's face as the room view draws it: the face its package makes,
// with the action units its person redefined (PROTOCOL.md 5.17) carried onto
// that face in place of the shipped ones. Package and units may come in
// either order: units that come first wait for the package, a new package
// (the full one after the preview) gets the avatar's units again, and an
// empty set (a restore) brings back the shipped units. No renderer, no lock.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "fw/codec/messages.hpp"
#include "fw/render/avatar_appearance.hpp"

namespace fw::client {

class RedefinedFaces {
 public:
  using Face = std::shared_ptr<const render::AvatarAppearance>;

  /// The avatar's package made `shipped` (its face with the shipped units).
  /// Returns the face to draw: `shipped` itself, or a copy with the avatar's
  /// redefined units.
  Face package_arrived(std::uint32_t avatar, Face shipped, std::string& error);
  /// The avatar's newest units. Returns the face to draw now, or null while
  /// its package is on its way (the units wait for it). A set the face
  /// cannot take (a vertex past it) leaves the shipped units, with `error`.
  Face units_arrived(const codec::UnitMorphs& units, std::string& error);
  /// The avatar left.
  void forget(std::uint32_t avatar);

 private:
  struct Avatar {
    Face shipped;
    std::optional<codec::UnitMorphs> units;
  };
  Face drawn(const Avatar& known, std::string& error) const;
  std::map<std::uint32_t, Avatar> avatars_;
};

}  // namespace fw::client
