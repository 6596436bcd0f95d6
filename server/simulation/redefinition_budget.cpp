#include "redefinition_budget.hpp"

#include <algorithm>

namespace fw::server {

std::optional<double> RedefinitionBudget::take(std::size_t bytes, double now_s) {
  tokens_ = std::min(kBurstBytes, tokens_ + std::max(0.0, now_s - last_s_) * kBytesPerSecond);
  last_s_ = std::max(last_s_, now_s);
  const auto wanted = static_cast<double>(bytes);
  if (wanted <= tokens_) {
    tokens_ -= wanted;
    return std::nullopt;
  }
  return (wanted - tokens_) / kBytesPerSecond;
}

}  // namespace fw::server
