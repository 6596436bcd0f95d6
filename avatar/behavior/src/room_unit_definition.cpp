// An AU definition in a room (room_script.hpp): held to the room's bounds,
// made into a morph of the generic face and split over the unit's channels.
#include <cmath>

#include "fw/behavior/au_definition_morph.hpp"
#include "fw/behavior/room_script.hpp"

namespace fw::behavior {
namespace {

// Within this of x = 0 a vertex is on the midline: both sides share it.
constexpr float kMidline = 1e-4f;

// The part of `morph` on one side of the face (the person's left is +x).
model::Morph side_of(const model::Morph& morph, const model::GenericFace& face, codec::AuSide side) {
  model::Morph part = morph;
  for (std::size_t v = 0; v < part.vertex_delta.size(); ++v) {
    const float x = face.skin.positions[v].x;
    const float share = std::abs(x) < kMidline ? 0.5f : ((x > 0) == (side == codec::AuSide::left) ? 1.0f : 0.0f);
    part.vertex_delta[v] *= share;
    part.uv_delta[v] *= share;
  }
  return part;
}

std::string streamed_units() {
  std::string list;
  for (const std::uint8_t au : codec::kActionUnits) list += (list.empty() ? "" : ", ") + std::to_string(au);
  return list;
}

std::string number(double x) {
  std::string text = std::to_string(x);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

std::string read_unit_definition(const script::AuDefinition& definition, const model::GenericFace& face,
                                 UnitDefinition& out) {
  const int au = definition.au;
  const std::string unit = "AU " + std::to_string(au);
  if (!definition.carried)
    return unit + " is not one of the units a face streams (" + streamed_units() + "): define one of those";
  if (definition.displacements.size() > kMaxRoomAuDisplacements)
    return unit + " moves " + std::to_string(definition.displacements.size()) + " control points; at most " +
           std::to_string(kMaxRoomAuDisplacements) + " are taken: move fewer, the skin around each follows";
  for (const script::ControlPointDisplacement& d : definition.displacements)
    for (const double x : d.displacement)
      if (std::abs(x) > kMaxRoomAuDisplacement)
        return unit + " moves " + d.region + " " + std::to_string(d.point) + " by " + number(x) +
               "; at most " + number(kMaxRoomAuDisplacement) +
               " along each axis (units of a face 200 wide) are taken: move it less";
  UnitDefinition read;
  read.au = au;
  if (definition.displacements.empty()) {
    read.restore = true;  // AU n / end: the shipped unit again
  } else {
    std::string error;
    const std::optional<model::Morph> morph = au_definition_morph(definition, face, error);
    if (!morph) return unit + ": " + error;
    if (codec::is_bilateral(au)) {
      read.morphs[static_cast<std::size_t>(codec::au_channel(au, codec::AuSide::left))] =
          side_of(*morph, face, codec::AuSide::left);
      read.morphs[static_cast<std::size_t>(codec::au_channel(au, codec::AuSide::right))] =
          side_of(*morph, face, codec::AuSide::right);
    } else {
      read.morphs[static_cast<std::size_t>(codec::au_channel(au, codec::AuSide::both))] = *morph;
    }
  }
  out = std::move(read);
  return {};
}

}  // namespace fw::behavior
