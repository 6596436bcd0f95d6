#include "endpoint.hpp"

#include <charconv>
#include <sstream>

namespace fw::server {

std::optional<boost::asio::ip::tcp::endpoint> parse_endpoint(std::string_view text, std::string& error) {
  const auto fail = [&](const std::string& why) {
    std::ostringstream message;
    message << "'" << text << "' is not an ADDR:PORT endpoint (" << why
            << "); write it like 127.0.0.1:8080 or [::1]:8080";
    error = message.str();
    return std::nullopt;
  };
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos) return fail("no port");
  std::string_view host = text.substr(0, colon);
  const std::string_view port_text = text.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  unsigned port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || end != port_text.data() + port_text.size() || port > 65535)
    return fail("the port must be a number from 0 to 65535");
  boost::system::error_code address_error;
  const auto address = boost::asio::ip::make_address(std::string(host), address_error);
  if (address_error) return fail("the address must be a numeric IPv4 or IPv6 address");
  return boost::asio::ip::tcp::endpoint(address, static_cast<unsigned short>(port));
}

}  // namespace fw::server
