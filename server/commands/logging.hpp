#pragma once
// spdlog set up for the server: human lines on stderr, or JSON lines
// ({"time", "level", "msg"}) for log collectors.
#include <string>

namespace fw::server {

void configure_logging(const std::string& level, bool json_lines);

}  // namespace fw::server
