#pragma once
// One avatar's action units as its person redefined them with a face
// script's AU definitions (avatar/behavior room_script.hpp), and the
// measurement of its face that uses them.
//
// A redefined unit moves by its morph alone: the physics face is not driven
// by it (its muscles make the shipped unit, which the unit no longer means;
// the person drew a shape, not a muscle), so the unit follows its target with
// the muscles' activation time constants, as a face without physics does.
// The face is measured against the avatar's own basis, the shipped rows with
// the redefined ones in their place: the simulated surface plus each
// redefined unit's morph at its weight, projected by least squares. So a
// redefined unit that overlaps a shipped one (a new brow raiser where AU 2
// pulls too) is told from it as the clients will rebuild both.
//
// The morphs are kept as the wire carries them (model/unit_morphs.hpp), so
// the server measures with exactly the morphs every client rebuilds with.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fw/behavior/room_script.hpp"
#include "fw/codec/messages.hpp"
#include "fw/model/unit_morphs.hpp"
#include "fw/physics/au_projection.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::server {

class RedefinedUnits {
 public:
  using Weights = std::array<float, codec::kAuChannelCount>;

  /// Applies a script's definitions, all or none: "" when taken, else why
  /// not (more than behavior::kMaxRedefinedUnitsPerAvatar units at once).
  /// A taken change raises the version, even one that changes nothing seen.
  std::string apply(const std::vector<behavior::UnitDefinition>& units);
  /// Takes the set another server kept (a room taken over, server/CLUSTER.md)
  /// as it was: its morphs as the wire carries them, and its version, so that
  /// the next change is newer than what the clients hold. "" when taken, else
  /// why not (a set no redefinition makes: more units than an avatar holds,
  /// a vertex past the generic face).
  std::string restore(const codec::UnitMorphs& message);

  bool any() const { return !morphs_.empty(); }
  bool redefined(std::size_t channel) const { return morphs_.contains(channel); }
  /// 0 until the first change, then +1 with each.
  std::uint32_t version() const { return version_; }
  /// Redefined channels' generic morphs, as carried on the wire.
  const model::UnitMorphSet& morphs() const { return morphs_; }
  /// The message that tells clients of the whole set (PROTOCOL.md 5.17).
  codec::UnitMorphs message(std::uint32_t avatar) const;

  /// The targets the physics face is driven by: the redefined units' at 0.
  Weights physics_targets(Weights targets) const;
  /// The face's weights: `simulation`'s surface plus each redefined unit's
  /// morph at its weight in `own` (the units' own tracks), projected on the
  /// avatar's basis; `weights` warm-starts the projection and takes the result.
  void measure(const physics::FaceSimulation& simulation, const Weights& own, Weights& weights) const;

 private:
  /// Makes `morphs` the set, and the basis the face is measured on.
  void take(model::UnitMorphSet morphs);

  std::uint32_t version_ = 0;
  model::UnitMorphSet morphs_;
  std::optional<physics::AuBasis> basis_;  ///< shipped rows with the redefined ones; set while any()
};

}  // namespace fw::server
