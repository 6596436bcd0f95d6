#include "peer_address.hpp"

namespace fw::server {

namespace ip = boost::asio::ip;

std::string address_key(const ip::address& address) {
  if (address.is_v4()) return address.to_string();
  const ip::address_v6 v6 = address.to_v6();
  if (v6.is_v4_mapped()) return ip::make_address_v4(ip::v4_mapped, v6).to_string();
  ip::address_v6::bytes_type bytes = v6.to_bytes();
  for (std::size_t i = 8; i < bytes.size(); ++i) bytes[i] = 0;
  return ip::address_v6(bytes).to_string() + "/64";
}

std::string address_key(std::string_view text) {
  boost::system::error_code ec;
  const ip::address address = ip::make_address(std::string(text), ec);
  return ec ? std::string(text) : address_key(address);
}

std::string address_group(const ip::address& address) {
  ip::address_v6 v6;
  if (address.is_v4()) {
    v6 = ip::make_address_v6(ip::v4_mapped, address.to_v4());
  } else {
    v6 = address.to_v6();
  }
  if (v6.is_v4_mapped()) {
    ip::address_v4::bytes_type bytes = ip::make_address_v4(ip::v4_mapped, v6).to_bytes();
    bytes[3] = 0;
    return ip::address_v4(bytes).to_string() + "/24";
  }
  ip::address_v6::bytes_type bytes = v6.to_bytes();
  for (std::size_t i = 6; i < bytes.size(); ++i) bytes[i] = 0;
  return ip::address_v6(bytes).to_string() + "/48";
}

std::string address_group(std::string_view text) {
  // An address_key() of IPv6 carries its "/64"; the address is before it.
  const std::string_view address_text = text.substr(0, text.find('/'));
  boost::system::error_code ec;
  const ip::address address = ip::make_address(std::string(address_text), ec);
  return ec ? std::string(text) : address_group(address);
}

}  // namespace fw::server
