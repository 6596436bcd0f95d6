#pragma once
// How many face-lab previews (PROTOCOL.md 5.16) run at once, on the server
// and per address, and whether one more may start. A preview is a private
// room of one with its own tick and physics face: bounded like rooms, but
// apart from them, so that previews never take the rooms people meet in,
// nor rooms the previews. A preview counts until its room closes (its page
// went, or was idle for PreviewLimits::idle). Not thread-safe:
// RoomRegistry holds its lock around it.
#include <chrono>
#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "fw/codec/messages.hpp"
#include "server_config.hpp"

namespace fw::server {

/// Why a preview may not start: the closing it is refused with, and what to do.
struct PreviewRefusal {
  codec::CloseCode code = codec::CloseCode::server_full;
  std::string why;
};

class PreviewCounts {
 public:
  explicit PreviewCounts(PreviewLimits limits) : limits_(limits) {}

  /// Whether `address` (address_key()) may start one more preview now.
  std::optional<PreviewRefusal> may_open(const std::string& address) const;
  void opened(const std::string& room, const std::string& address);
  /// The preview's room closed (nothing if `room` is no preview).
  void closed(const std::string& room);

  bool is_preview(const std::string& room) const { return owners_.contains(room); }
  std::size_t open() const { return owners_.size(); }
  std::size_t held_by(const std::string& address) const;

 private:
  PreviewLimits limits_;
  std::map<std::string, std::string> owners_;  ///< room -> the address that opened it
  std::map<std::string, std::size_t> by_address_;
};

}  // namespace fw::server
