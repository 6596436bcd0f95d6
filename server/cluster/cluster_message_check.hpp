#pragma once
// What another node says over Redis is checked like what a client says: a
// cluster's channels are open to anyone who can reach its Redis, and a
// message that reaches a room reaches people. Each check answers why a
// message could not have come from a node of this build doing its job
// (lengths past what a node ever writes, numbers that are not finite or
// out of the codec's ranges, a client message of the wrong kind, names no
// node can have), or nullopt when it could. A refused message is dropped
// whole and counted (Abuse::cluster_message); none is repaired, except
// faces a hair outside their range, which the owner's physics can produce
// and the encoder clamps anyway.
//
// Who may send what (only the holder of a room's lease sends its news
// down, only a live node sends requests up) needs Redis, and is checked by
// ClusterNode (cluster_node_checks.cpp).
#include <optional>
#include <string>
#include <string_view>

#include "abuse_limits.hpp"
#include "bridge_message.hpp"
#include "cluster_limits.hpp"

namespace fw::server::cluster_check {

/// The longest things nodes write, past which a message is refused.
inline constexpr std::size_t kMaxNodeNameBytes = 64;      ///< as --node allows
inline constexpr std::size_t kMaxAddressBytes = 64;       ///< an address_key(): an IPv4 address or an IPv6 /64
inline constexpr std::size_t kMaxHashBytes = 64;          ///< a secret_hash(): 43 base64url characters
inline constexpr std::size_t kMaxJoinRefBytes = kMaxNodeNameBytes + 1 + 20;  ///< "NODE/NUMBER"
inline constexpr std::size_t kMaxRosterMembers = 64;      ///< --room-size at most
inline constexpr std::size_t kMaxRosterBytes = 64 * 1024; ///< every encoded client message a down message carries
/// Lines of one limits message: far more than a node reports in a beat
/// (its connections, and the addresses that spent since the last beat,
/// a flood of new ones included), so that its news is never refused when
/// it matters most.
inline constexpr std::size_t kMaxLimitsLines = 65536;

/// A node name as --node allows it: 1 to 64 letters, digits, - _ . or :.
bool plausible_node_name(std::string_view name);

/// Why `message`, read from a room's down channel, cannot be its owner's;
/// nullopt when it can. Faces a little outside the codec's ranges (no more
/// than a tenth of the range; an eye's is its own plus the head's, as the
/// codec carries it) are clamped into them.
std::optional<std::string> refusal_of(bridge::Down& message);
/// Why `message`, read from a room's up channel, cannot be a bridging
/// node's request; nullopt when it can.
std::optional<std::string> refusal_of(const bridge::Up& message);
/// Why a member's record, or a room's moods, read from a room's record in
/// Redis (what a takeover restores) cannot be what its owner kept.
std::optional<std::string> refusal_of(const bridge::MemberRecord& member);
std::optional<std::string> refusal_of(const bridge::RoomState& state);
/// Why `news`, read from the limits channel, cannot be a node's report:
/// more lines than a node holds connections, spending that is not a finite
/// number a node could have taken in a few beats under `limits`, more
/// connections for one address than it may hold. nullopt when it can.
std::optional<std::string> refusal_of(const LimitsNews& news, const AbuseLimits& limits);

}  // namespace fw::server::cluster_check
