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

/// The network an address belongs to, for limits that count neighbours
/// together: the /24 of an IPv4 address ("192.0.2.0/24"), the /48 of an
/// IPv6 one ("2001:db8:1::/48"; a site's allocation). Someone who rents
/// many addresses usually gets them in one such block, so a share counted
/// per block holds where a share per address would be multiplied by the
/// block's size. An IPv4 address mapped into IPv6 counts as IPv4.
std::string address_group(const boost::asio::ip::address& address);
/// The same from an address's text or an address_key(); text that is no
/// address is its own group.
std::string address_group(std::string_view text);

}  // namespace fw::server
