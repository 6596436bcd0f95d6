#pragma once
// Action units a person redefined (a face script's AU definitions, turned
// into morphs of the generic face by the server): their form on the wire
// (codec::UnitMorphs, server/PROTOCOL.md 5.17) and their place in an
// avatar's model. The server measures with the morphs as the wire carries
// them, and every client carries those onto the avatar's fit exactly as the
// shipped units are carried (motion_cloning.hpp), so all see one face.
#include <map>
#include <optional>
#include <string>

#include "fw/codec/messages.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::model {

/// Redefined units by FaceParams channel, as morphs of the generic face.
using UnitMorphSet = std::map<std::size_t, Morph>;

/// A generic morph as the wire carries it: the vertices it moves, their
/// displacements rounded to the wire's step (texture slides are not carried:
/// a redefined unit moves the skin and its picture together).
codec::UnitMorphs::Unit unit_morph_message(std::size_t channel, const Morph& generic);

/// The set a message carries, as morphs of a face of `vertex_count` skin
/// vertices. nullopt and `error` when a vertex is past the face.
std::optional<UnitMorphSet> unit_morph_set(const codec::UnitMorphs& message, std::size_t vertex_count,
                                           std::string& error);

/// The morph as a client will rebuild it from the wire (rounded to the step).
Morph as_carried(std::size_t channel, const Morph& generic);

/// The avatar's units: each unit in `units` is its generic morph carried
/// onto the fit, every other the shipped unit (generic.action_units) carried
/// onto it again, so an empty set restores the shipped face.
void set_unit_morphs(AvatarModel& avatar, const GenericFace& generic, const UnitMorphSet& units);

}  // namespace fw::model
