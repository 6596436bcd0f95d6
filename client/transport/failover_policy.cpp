#include "failover_policy.hpp"

#include <algorithm>

namespace fw::client {

NextStep after_closing(codec::CloseCode code, bool could_upload_here) {
  using codec::CloseCode;
  switch (code) {
    // The person must change something (client version, token, name,
    // room); another server of the same community says the same.
    case CloseCode::protocol_error:
    case CloseCode::message_too_large:
    case CloseCode::unsupported_version:
    case CloseCode::room_full:
      return NextStep::stop;
    // 10 is also "unknown avatar", 4 also "not the key of this face": what a
    // server that never had the upload says. Elsewhere they are for good.
    case CloseCode::bad_request:
    case CloseCode::unauthorized:
      return could_upload_here ? NextStep::upload_here : NextStep::stop;
    // The server prepares the face again, for a few seconds: it is the one to ask.
    case CloseCode::avatar_being_prepared:
      return NextStep::same_server;
    // Shutting down, full, rate limited, timed out, or a code this client
    // does not know (a later server's): another server may take it.
    default:
      return NextStep::next_server;
  }
}

bool another_server_may_take_it(int http_status) {
  return http_status == 0 || http_status == 429 || http_status >= 500;
}

ServerRotation::ServerRotation(std::size_t count, std::size_t first)
    : count_(std::max<std::size_t>(count, 1)), current_(first % count_) {}

std::size_t ServerRotation::move_on() {
  current_ = (current_ + 1) % count_;
  return current_;
}

}  // namespace fw::client
