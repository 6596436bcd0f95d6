#include "preview_limits.hpp"

namespace fw::server {
namespace {

/// A preview that nobody uses ends after the idle time: the latest a place
/// frees without anyone closing a page.
std::string retry_text(const PreviewLimits& limits) {
  return "try again in " + std::to_string(limits.idle.count()) + " s at the latest";
}

}  // namespace

std::optional<PreviewRefusal> PreviewCounts::may_open(const std::string& address) const {
  if (held_by(address) >= limits_.per_address)
    return PreviewRefusal{codec::CloseCode::rate_limited,
                          "your address has " + std::to_string(limits_.per_address) +
                              " face-lab previews open; close one of those pages, or " + retry_text(limits_)};
  if (owners_.size() >= limits_.max)
    return PreviewRefusal{codec::CloseCode::server_full,
                          "the server runs its most face-lab previews (" + std::to_string(limits_.max) + "); " +
                              retry_text(limits_)};
  return std::nullopt;
}

void PreviewCounts::opened(const std::string& room, const std::string& address) {
  if (owners_.emplace(room, address).second) ++by_address_[address];
}

void PreviewCounts::closed(const std::string& room) {
  const auto it = owners_.find(room);
  if (it == owners_.end()) return;
  const auto count = by_address_.find(it->second);
  if (count != by_address_.end() && --count->second == 0) by_address_.erase(count);
  owners_.erase(it);
}

std::size_t PreviewCounts::held_by(const std::string& address) const {
  const auto it = by_address_.find(address);
  return it == by_address_.end() ? 0 : it->second;
}

}  // namespace fw::server
