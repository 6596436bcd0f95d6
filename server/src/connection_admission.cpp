#include "connection_admission.hpp"

namespace fw::server {

Admission ConnectionAdmission::admit(const std::string& address_key) {
  Admission admission;
  // Counted first, then checked: two accepts at once cannot both take the last place.
  if (total_->fetch_add(1) >= max_total_) {
    total_->fetch_sub(1);
    admission.refusal = Abuse::connection_limit;
    return admission;
  }
  if (!addresses_.open_connection(address_key)) {
    total_->fetch_sub(1);
    admission.refusal = Abuse::address_connection_limit;
    return admission;
  }
  admission.ticket.emplace(ConnectionSlot(addresses_, address_key), total_);
  return admission;
}

Admission ConnectionAdmission::admit_from_trusted_proxy() {
  Admission admission;
  if (total_->fetch_add(1) >= max_total_) {
    total_->fetch_sub(1);
    admission.refusal = Abuse::connection_limit;
    return admission;
  }
  admission.ticket.emplace(ConnectionSlot(), total_);
  return admission;
}

}  // namespace fw::server
