#pragma once
// The key under which limits count a peer: its IPv4 address, or the /64 of
// its IPv6 address (one subscriber line gets a whole /64, so counting single
// IPv6 addresses would let one person have 2^64 of them). An IPv4 address
// mapped into IPv6 counts as the IPv4 address.
#include <string>
#include <string_view>

#include <boost/asio/ip/address.hpp>

namespace fw::server {

std::string address_key(const boost::asio::ip::address& address);
/// The same from an address's text (a peer string); text that is no
/// address is its own key.
std::string address_key(std::string_view text);

}  // namespace fw::server
