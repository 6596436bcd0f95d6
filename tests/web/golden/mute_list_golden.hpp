#pragma once
// Golden file of muting for oneself (client/room/mute_list: whom a list of
// names mutes, and the still face a muted person is drawn with), which the
// browser's web/room/mute_list.js ports.
#include <nlohmann/json.hpp>

namespace fw::test::web_golden {

nlohmann::json mute_list_golden();

}  // namespace fw::test::web_golden
