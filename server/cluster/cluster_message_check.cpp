#include "cluster_message_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "display_name.hpp"
#include "fw/codec/codec.hpp"

namespace fw::server::cluster_check {
namespace {

using Refusal = std::optional<std::string>;

bool plausible_avatar(std::uint32_t id) { return id >= 1 && id <= codec::kMaxAvatarIdValue; }

bool within(std::string_view text, std::size_t max_bytes) { return text.size() <= max_bytes; }

/// Letters, digits and - _ . : only: what asset ids, node names and hashes are made of.
bool plain(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ':';
  });
}

/// An address_key() as text: an IPv4 or IPv6 address, or an IPv6 /64.
bool plausible_address(std::string_view text) {
  return !text.empty() && within(text, kMaxAddressBytes) &&
         std::all_of(text.begin(), text.end(), [](char c) {
           return std::isxdigit(static_cast<unsigned char>(c)) || c == '.' || c == ':' || c == '/';
         });
}

bool plausible_hash(std::string_view text) { return within(text, kMaxHashBytes) && plain(text); }

/// Whether `bytes` is one whole client message of the kind of `Message`, as
/// the codec's reader checks those (lengths, UTF-8, control characters).
template <class Message>
bool reads_as(const bridge::Bytes& bytes, Message& message) {
  return codec::read_message(bytes, message) == codec::MessageError::ok;
}

/// Whether `text` passes the codec's checks of a client's chat line.
bool clean_chat(const std::string& text) {
  if (text.empty() || text.size() > codec::kMaxChatBytes) return false;
  bridge::Bytes bytes;
  codec::write_message(codec::Chat{0, text}, bytes);
  codec::Chat back;
  return reads_as(bytes, back);
}

/// Whether `text` passes the codec's checks of a closing's reason.
bool clean_reason(const std::string& text) {
  if (text.size() > codec::kMaxReasonBytes) return false;
  bridge::Bytes bytes;
  codec::write_message(codec::Closing{codec::CloseCode::normal, text}, bytes);
  codec::Closing back;
  return reads_as(bytes, back);
}

bool plausible_display_name(const std::string& name) {
  std::string normalized;
  return !name.empty() && within(name, codec::kMaxDisplayNameBytes) && normalize_display_name(name, normalized).empty();
}

bool plausible_asset(std::string_view asset) { return within(asset, codec::kMaxAssetIdBytes) && plain(asset); }

bool plausible_seat(const codec::SeatInfo& seat) {
  for (const float v : {seat.x_mm, seat.y_mm, seat.z_mm})
    if (!std::isfinite(v) || std::abs(v) > 32767.f) return false;
  return std::isfinite(seat.facing_yaw_rad) && std::abs(seat.facing_yaw_rad) <= std::numbers::pi_v<float> + 1e-3f;
}

/// A set of unit morphs as the owner sends it (PROTOCOL.md 5.17): one
/// whole message within its bounds (at most 8 channels, 1024 moves each,
/// channels and vertices increasing), of `avatar`, after a redefinition.
Refusal unit_morphs_refusal(const bridge::Bytes& bytes, std::uint32_t avatar) {
  codec::UnitMorphs set;
  if (!reads_as(bytes, set)) return "no UnitMorphs message within its bounds";
  if (set.avatar != avatar) return "a set of another avatar";
  if (set.version == 0) return "a set of version 0, which no redefinition makes";
  return std::nullopt;
}

Refusal member_refusal(const bridge::MemberRecord& m) {
  if (!plausible_avatar(m.info.id)) return "a member's avatar id is out of range";
  if (!plausible_display_name(m.info.name)) return "a member's name is no display name";
  if (!plausible_asset(m.info.asset)) return "a member's asset id is malformed";
  if (m.info.preview_bytes > codec::kMaxPackageBytes || m.info.full_bytes > codec::kMaxPackageBytes)
    return "a member's package sizes are past the largest package";
  if (!plausible_seat(m.info.seat)) return "a member's seat is not finite or off the table";
  if (!m.node.empty() && !plausible_node_name(m.node)) return "a member's node name is malformed";
  if (!m.address.empty() && !plausible_address(m.address)) return "a member's address is malformed";
  if (!plausible_hash(m.resume_hash)) return "a member's resume hash is malformed";
  if (!m.language.empty() && !codec::is_language_code(m.language)) return "a member's language is malformed";
  if (!m.unit_morphs.empty())
    if (auto why = unit_morphs_refusal(m.unit_morphs, m.info.id)) return "a member's unit morphs: " + *why;
  return std::nullopt;
}

/// The values channel `c` may carry: its field's range, or for an eye,
/// which the simulation turns past its own range to counter the head's
/// turn (the codec codes it as eye plus head), the sum of both ranges.
std::pair<float, float> carried_range(std::size_t c) {
  const auto& table = codec::channel_table();
  float low = static_cast<float>(table[c].min_q) * table[c].step;
  float high = static_cast<float>(table[c].max_q) * table[c].step;
  if (const int base = table[c].base; base >= 0) {
    const auto& b = table[static_cast<std::size_t>(base)];
    low += static_cast<float>(b.min_q) * b.step;
    high += static_cast<float>(b.max_q) * b.step;
  }
  return {low, high};
}

/// The faces of a tick: every number finite and within the range the codec
/// carries for its channel. The owner's physics may overshoot a range a
/// little (the encoder clamps it): such values are clamped here too; values
/// far out are no simulation's and refuse the message.
Refusal faces_refusal(std::vector<bridge::FaceEntry>& faces) {
  if (faces.size() > kMaxRosterMembers) return "more faces than a room holds";
  std::set<std::uint32_t> ids;
  const auto& table = codec::channel_table();
  for (bridge::FaceEntry& entry : faces) {
    if (!plausible_avatar(entry.id) || !ids.insert(entry.id).second) return "a face's avatar id is out of range or repeated";
    for (std::size_t c = 0; c < codec::kChannelCount; ++c) {
      const float value = codec::channel_value(entry.face, c);
      const auto [low, high] = carried_range(c);
      const float slack = 0.1f * (high - low);
      if (!std::isfinite(value)) return "a face's " + std::string(table[c].name) + " is not a finite number";
      if (value < low - slack || value > high + slack)
        return "a face's " + std::string(table[c].name) + " is far outside its range";
      codec::set_channel_value(entry.face, c, std::clamp(value, low, high));
    }
  }
  return std::nullopt;
}

}  // namespace

bool plausible_node_name(std::string_view name) {
  return !name.empty() && within(name, kMaxNodeNameBytes) && plain(name);
}

Refusal refusal_of(const bridge::MemberRecord& member) { return member_refusal(member); }

Refusal refusal_of(const bridge::RoomState& state) {
  std::set<std::uint32_t> ids;
  for (const auto& mood : state.moods) {
    if (!plausible_avatar(mood.avatar) || !ids.insert(mood.avatar).second) return "a mood's avatar id is out of range or repeated";
    for (const float v : mood.values)
      if (!std::isfinite(v)) return "a mood that is not a finite number";
  }
  return std::nullopt;
}

Refusal refusal_of(bridge::Down& m) {
  if (!plausible_node_name(m.owner)) return "the sender's node name is malformed";
  switch (m.kind) {
    case bridge::DownKind::roster: {
      if (m.members.size() > kMaxRosterMembers) return "a roster of more members than a room holds";
      std::set<std::uint32_t> ids;
      for (const auto& member : m.members) {
        if (auto why = member_refusal(member)) return "roster: " + *why;
        if (!ids.insert(member.info.id).second) return "roster: an avatar id twice";
      }
      codec::Attention attention;
      if (!reads_as(m.attention, attention)) return "roster: its attention is no Attention message";
      return std::nullopt;
    }
    case bridge::DownKind::joined:
      if (!within(m.join_ref, kMaxJoinRefBytes)) return "joined: the join reference is too long";
      if (auto why = member_refusal(m.member)) return "joined: " + *why;
      return std::nullopt;
    case bridge::DownKind::refused:
      if (m.join_ref.empty() || !within(m.join_ref, kMaxJoinRefBytes)) return "refused: no plausible join reference";
      if (static_cast<std::uint16_t>(m.code) > static_cast<std::uint16_t>(codec::CloseCode::avatar_being_prepared))
        return "refused: an unknown close code";
      if (!clean_reason(m.reason)) return "refused: the reason is too long or not clean text";
      return std::nullopt;
    case bridge::DownKind::left:
      if (!plausible_avatar(m.avatar)) return "left: the avatar id is out of range";
      return std::nullopt;
    case bridge::DownKind::attention: {
      codec::Attention attention;
      if (!reads_as(m.attention, attention)) return "attention: no Attention message";
      return std::nullopt;
    }
    case bridge::DownKind::seats: {
      codec::Seats seats;
      if (!reads_as(m.message, seats)) return "seats: no Seats message";
      return std::nullopt;
    }
    case bridge::DownKind::chat: {
      codec::Chat chat;
      if (m.avatar > codec::kMaxAvatarIdValue) return "chat: the addressee's avatar id is out of range";
      if (!reads_as(m.message, chat) || !clean_chat(chat.text)) return "chat: no chat line a client could have written";
      return std::nullopt;
    }
    case bridge::DownKind::speaking: {
      codec::Speaking speaking;
      if (m.avatar != 0) return "speaking: it goes to everyone (avatar 0)";
      if (!reads_as(m.message, speaking) || !plausible_avatar(speaking.avatar))
        return "speaking: no Speaking message of an avatar";
      return std::nullopt;
    }
    case bridge::DownKind::result: {
      codec::CommandResult result;
      if (!plausible_avatar(m.avatar)) return "result: the addressee's avatar id is out of range";
      if (!reads_as(m.message, result)) return "result: no CommandResult message";
      return std::nullopt;
    }
    case bridge::DownKind::unit_morphs:
      if (!plausible_avatar(m.avatar)) return "unit morphs: the avatar id is out of range";
      if (auto why = unit_morphs_refusal(m.message, m.avatar)) return "unit morphs: " + *why;
      return std::nullopt;
    case bridge::DownKind::tick:
      if (auto why = faces_refusal(m.faces)) return "tick: " + *why;
      return std::nullopt;
  }
  return "an unknown kind of message";
}

Refusal refusal_of(const bridge::Up& m) {
  if (!plausible_node_name(m.node)) return "the sender's node name is malformed";
  switch (m.kind) {
    case bridge::UpKind::sync: return std::nullopt;
    case bridge::UpKind::join:
      // A bridging node numbers its joins after its own name.
      if (!within(m.join_ref, kMaxJoinRefBytes) || m.join_ref.rfind(m.node + "/", 0) != 0)
        return "join: the join reference is not the sender's";
      if (!plausible_display_name(m.name)) return "join: the name is no display name";
      if (!plausible_asset(m.asset)) return "join: the asset id is malformed";
      if (!plausible_address(m.address)) return "join: the address is malformed";
      if (!plausible_hash(m.resume_hash)) return "join: the resume hash is malformed";
      if (!within(m.returning, codec::kMaxKeyBytes) || !plain(m.returning)) return "join: the resume key is malformed";
      if (!m.language.empty() && !codec::is_language_code(m.language)) return "join: the language is malformed";
      return std::nullopt;
    case bridge::UpKind::leave:
      if (!plausible_avatar(m.avatar)) return "leave: the avatar id is out of range";
      return std::nullopt;
    case bridge::UpKind::chat:
      if (!plausible_avatar(m.avatar)) return "chat: the avatar id is out of range";
      if (!clean_chat(m.text)) return "chat: no chat line a client could have written";
      return std::nullopt;
    case bridge::UpKind::command: {
      codec::Command command;
      if (!plausible_avatar(m.avatar)) return "command: the avatar id is out of range";
      if (!reads_as(m.command, command)) return "command: no Command message";
      return std::nullopt;
    }
  }
  return "an unknown kind of message";
}

Refusal refusal_of(const LimitsNews& news, const AbuseLimits& limits) {
  if (!plausible_node_name(news.node)) return "limits: the sender's node name is malformed";
  if (news.spent.size() + news.connections.size() + news.tokens.size() > kMaxLimitsLines)
    return "limits: more lines than a node has connections";
  for (const auto& spent : news.spent) {
    if (!plausible_address(spent.key)) return "limits: an address is malformed";
    // What a node reports is what its clients took since its last report:
    // at most a bucket's burst and what refills in a few beats. More is
    // no node's report (charge() bounds what any report can do anyway).
    const BucketRate rate = rate_of(limits, spent.rate);
    if (!std::isfinite(spent.tokens) || spent.tokens < 0) return "limits: spending that is not a finite amount";
    if (spent.tokens > 4 * (rate.burst + rate.per_second * 60)) return "limits: more spending than an address can do";
  }
  for (const auto& [key, count] : news.connections) {
    if (!plausible_address(key)) return "limits: an address is malformed";
    if (count > limits.connections_per_address) return "limits: more connections than an address may hold";
  }
  for (const auto& token : news.tokens) {
    if (token.token_hash.empty() || !plausible_hash(token.token_hash) || !plausible_hash(token.resume_hash))
      return "limits: a token hash is malformed";
    if (!token.taken_from.empty() && !plausible_node_name(token.taken_from))
      return "limits: a node name is malformed";
  }
  return std::nullopt;
}

}  // namespace fw::server::cluster_check
