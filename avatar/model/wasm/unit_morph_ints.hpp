#pragma once
// A unit morphs message's units (server/PROTOCOL.md 5.17) as JavaScript
// hands them over, flat int32s: the number of units, then per unit its
// channel and its number of moves, then per move the vertex and dx, dy, dz
// in the wire's steps. web/engine/avatar_model.js writes them from what
// web/protocol/session_read.js read; the checks are the codec reader's, so
// that the model is never handed what the wire could not carry.
#include <cstddef>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::wasm {

/// `count` moves (vertex, dx, dy, dz) taken with `next`, vertices strictly
/// increasing, displacements within 16 bits; false and `error` if not.
template <typename Next>
bool moves_from_ints(Next& next, std::int32_t count, std::vector<codec::UnitMorphs::Move>& out, std::string& error) {
  out.clear();
  for (std::int32_t m = 0; m < count; ++m) {
    std::int32_t vertex = 0;
    std::array<std::int32_t, 3> delta{};
    if (!next(vertex) || !next(delta[0]) || !next(delta[1]) || !next(delta[2]))
      return error = "list ends inside its moves", false;
    if (vertex < 0 || (!out.empty() && static_cast<std::uint32_t>(vertex) <= out.back().vertex))
      return error = "vertices do not increase", false;
    codec::UnitMorphs::Move move;
    move.vertex = static_cast<std::uint32_t>(vertex);
    for (int k = 0; k < 3; ++k) {
      if (delta[k] < std::numeric_limits<std::int16_t>::min() || delta[k] > std::numeric_limits<std::int16_t>::max())
        return error = "displacement is past 16 bits", false;
      move.delta[k] = static_cast<std::int16_t>(delta[k]);
    }
    out.push_back(move);
  }
  return true;
}

/// A preview surface's moves (server/PROTOCOL.md 5.18) as JavaScript hands
/// them over: the number of moves, then per move the vertex and dx, dy, dz.
inline bool surface_moves_from_ints(std::span<const std::int32_t> ints, std::vector<codec::UnitMorphs::Move>& moves,
                                    std::string& error) {
  std::size_t at = 0;
  const auto next = [&](std::int32_t& value) {
    if (at >= ints.size()) return false;
    value = ints[at++];
    return true;
  };
  std::int32_t count = 0;
  std::string why;
  if (!next(count) || count < 0 || count > static_cast<std::int32_t>(codec::kMaxUnitMorphMoves))
    why = "a move count of 0 .. " + std::to_string(codec::kMaxUnitMorphMoves) + " first";
  else if (!moves_from_ints(next, count, moves, why)) why = "its " + why;
  else if (at != ints.size()) why = std::to_string(ints.size() - at) + " numbers past the last move";
  if (why.empty()) return true;
  error = "preview surface: " + why;
  return false;
}

inline bool unit_morphs_from_ints(std::span<const std::int32_t> ints, codec::UnitMorphs& message, std::string& error) {
  std::size_t at = 0;
  const auto next = [&](std::int32_t& value) {
    if (at >= ints.size()) return false;
    value = ints[at++];
    return true;
  };
  const auto refuse = [&](std::string why) {
    error = "unit morphs: " + std::move(why);
    return false;
  };
  std::int32_t units = 0;
  if (!next(units)) return refuse("no unit count");
  if (units < 0 || units > static_cast<std::int32_t>(codec::kMaxRedefinedChannels))
    return refuse(std::to_string(units) + " units; at most " + std::to_string(codec::kMaxRedefinedChannels));
  message.units.clear();
  for (std::int32_t u = 0; u < units; ++u) {
    std::int32_t channel = 0, moves = 0;
    if (!next(channel) || !next(moves)) return refuse("the list ends inside unit " + std::to_string(u));
    if (channel < 0 || channel >= static_cast<std::int32_t>(codec::kAuChannelCount) ||
        (!message.units.empty() && channel <= message.units.back().channel))
      return refuse("channel " + std::to_string(channel) + " is not a later action-unit channel");
    if (moves < 0 || moves > static_cast<std::int32_t>(codec::kMaxUnitMorphMoves))
      return refuse(std::to_string(moves) + " moves; at most " + std::to_string(codec::kMaxUnitMorphMoves));
    codec::UnitMorphs::Unit unit;
    unit.channel = static_cast<std::uint8_t>(channel);
    if (!moves_from_ints(next, moves, unit.moves, error))
      return refuse("channel " + std::to_string(channel) + "'s " + error);
    message.units.push_back(std::move(unit));
  }
  if (at != ints.size()) return refuse(std::to_string(ints.size() - at) + " numbers past the last unit");
  return true;
}

}  // namespace fw::wasm
