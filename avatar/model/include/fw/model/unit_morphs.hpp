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
#include <vector>

#include "fw/codec/messages.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::model {

/// Redefined units by FaceParams channel, as morphs of the generic face.
using UnitMorphSet = std::map<std::size_t, Morph>;

/// A displacement (model units) in the wire's steps (1/kUnitMorphStepsPerUnit),
/// rounded and held to 16 bits: a unit morph's, a preview surface's.
std::int16_t unit_morph_steps(float units);

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

/// A displacement of the generic face's skin as the wire carries it (a
/// face-lab preview surface's moves, server/PROTOCOL.md 5.18), carried onto
/// the avatar's fit as its units are: one offset per skin vertex of the
/// fit, model units, added to the face its frames rebuild. nullopt and
/// `error` when a vertex is past the generic face's `vertex_count`.
std::optional<std::vector<glm::vec3>> carried_surface(const AvatarModel& avatar,
                                                      const std::vector<codec::UnitMorphs::Move>& moves,
                                                      std::size_t vertex_count, std::string& error);

}  // namespace fw::model
