#include "reconnect_policy_golden.hpp"

#include <cstdint>

#include "failover_policy.hpp"
#include "room_session.hpp"

namespace fw::test::web_golden {
namespace {

const char* step_name(client::NextStep step) {
  switch (step) {
    case client::NextStep::same_server: return "same_server";
    case client::NextStep::next_server: return "next_server";
    case client::NextStep::upload_here: return "upload_here";
    case client::NextStep::stop: return "stop";
  }
  return "?";
}

}  // namespace

nlohmann::json reconnect_policy_golden() {
  nlohmann::json out;
  out["about"] =
      "client/transport/failover_policy.cpp (after_closing, after_drop) and RoomSession::backoff, written by "
      "tests/web/golden; web/room/reconnect_policy.js must decide the same (the browser never uploads a "
      "face from the room page: could_upload_here false)";
  // Every code a closing can carry that the protocol defines, and some it
  // does not define yet (a later server's): those must move on.
  nlohmann::json closings = nlohmann::json::array();
  for (std::uint16_t code : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 99, 255, 256, 65535}) {
    const auto close_code = static_cast<codec::CloseCode>(code);
    closings.push_back({{"code", code},
                        {"step", step_name(client::after_closing(close_code, false))},
                        {"step_could_upload_here", step_name(client::after_closing(close_code, true))}});
  }
  out["closings"] = closings;
  out["drop"] = step_name(client::after_drop());
  // The wait before attempt n+1 after n failed attempts in a row (a welcome
  // starts the count again), past the cap.
  nlohmann::json backoff = nlohmann::json::array();
  for (int failed = 1; failed <= 10; ++failed)
    backoff.push_back({{"failed_attempts", failed}, {"delay_ms", client::RoomSession::backoff(failed).count()}});
  out["backoff"] = backoff;
  return out;
}

}  // namespace fw::test::web_golden
