#pragma once
// Golden file of the client's reconnection decisions
// (client/transport/failover_policy, RoomSession::backoff), which the browser's
// web/room/reconnect_policy.js ports: what follows every close code, with
// and without a face of one's own to upload, and the back-off after each
// failed attempt in a row.
#include <nlohmann/json.hpp>

namespace fw::test::web_golden {

nlohmann::json reconnect_policy_golden();

}  // namespace fw::test::web_golden
