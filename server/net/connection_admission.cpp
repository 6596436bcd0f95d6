#include "connection_admission.hpp"

#include "peer_address.hpp"

namespace fw::server {

Admission ConnectionAdmission::admit(const std::string& address_key, Clock::time_point now, bool must_evict) {
  Admission admission;
  if (!addresses_.open_connection(address_key)) {
    admission.refusal = Abuse::address_connection_limit;
    admission.retry_after = shares_->retry_for_address(address_key, now);
    return admission;
  }
  ConnectionSlot address(addresses_, address_key);  // given back if the shares refuse
  auto verdict = shares_->admit(address_key, address_group(address_key), now, must_evict);
  if (verdict.id == 0) {
    admission.refusal = verdict.refusal;
    admission.retry_after = verdict.retry_after;
    return admission;
  }
  admission.evicted = std::move(verdict.evicted);
  admission.ticket.emplace(std::move(address), shares_, verdict.id);
  return admission;
}

Admission ConnectionAdmission::admit_from_trusted_proxy(Clock::time_point now, bool must_evict) {
  Admission admission;
  auto verdict = shares_->admit("", "", now, must_evict);
  if (verdict.id == 0) {
    admission.refusal = verdict.refusal;
    admission.retry_after = verdict.retry_after;
    return admission;
  }
  admission.evicted = std::move(verdict.evicted);
  admission.ticket.emplace(ConnectionSlot(), shares_, verdict.id);
  return admission;
}

}  // namespace fw::server
