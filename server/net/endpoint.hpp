#pragma once
// Parsing ADDR:PORT flags into Asio endpoints.
#include <optional>
#include <string>
#include <string_view>

#include <boost/asio/ip/tcp.hpp>

namespace fw::server {

/// Parses "127.0.0.1:8080", "[::1]:8080" or "0.0.0.0:0" (port 0: any free port).
/// nullopt and `error` (saying what form is expected) if it is not one.
std::optional<boost::asio::ip::tcp::endpoint> parse_endpoint(std::string_view text, std::string& error);

}  // namespace fw::server
