#pragma once
// Proxies the operator trusts (--trusted-proxy CIDR), and the client address
// such a proxy forwards. Behind a proxy (a load balancer, an ingress, the
// compose file's) every connection comes from the proxy's address, so the
// per-address limits would count the proxy, not people; for a request whose
// TCP peer is a trusted proxy, the client is the rightmost address of its
// X-Forwarded-For (or, without one, its Forwarded: for=) that is not itself a
// trusted proxy. Everything to the left of that address is whatever the
// client chose to send, so it is never read: garbage there can neither
// choose the client's address nor push it into the proxy's bucket. Pure
// logic, no sockets.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <boost/asio/ip/address.hpp>

namespace fw::server {

/// One network, IPv4 or IPv6, and its prefix length.
struct AddressRange {
  boost::asio::ip::address network;
  unsigned prefix = 0;

  /// Whether `address` is inside; an IPv4 address mapped into IPv6 counts as
  /// the IPv4 address (a dual-stack listener sees ::ffff:10.0.0.1).
  bool contains(const boost::asio::ip::address& address) const;
  std::string to_string() const;
};

/// "10.0.0.0/8", "fd00::/8" or one address ("127.0.0.1" is 127.0.0.1/32);
/// nullopt and `error` (what was wrong and what to write instead) for
/// anything else, a network with bits set past its prefix included.
std::optional<AddressRange> parse_address_range(std::string_view text, std::string& error);

class TrustedProxies {
 public:
  /// Adds a range (parse_address_range()); false and `error` if it is none.
  bool add(std::string_view range, std::string& error);
  bool contains(const boost::asio::ip::address& address) const;
  bool empty() const { return ranges_.empty(); }
  const std::vector<AddressRange>& ranges() const { return ranges_; }

 private:
  std::vector<AddressRange> ranges_;
};

/// A request's forwarding headers as they came: each header line's value, in
/// order (several lines of one header make one list, RFC 9110 5.3).
struct ForwardingHeaders {
  std::vector<std::string_view> x_forwarded_for;
  std::vector<std::string_view> forwarded;
};

/// Whom a request is from.
struct ClientAddress {
  enum class Source {
    peer,       ///< the TCP peer itself: not a trusted proxy, or it forwarded nothing
    forwarded,  ///< the address a trusted proxy forwarded
    malformed,  ///< a trusted proxy's header named no address where it had to: the peer, and `problem`
  };
  boost::asio::ip::address address;
  Source source = Source::peer;
  std::string problem;  ///< for `malformed`: what was wrong, fit for a log line
};

/// The client of a request from `peer`. Headers count only when `peer` is
/// a trusted proxy; X-Forwarded-For wins over Forwarded when both came.
/// Entries may carry a port ("192.0.2.1:4711", "[2001:db8::1]:4711").
/// When every address in the list is a trusted proxy, the leftmost is the
/// client (a client inside the proxies' own network).
ClientAddress client_address(const TrustedProxies& proxies, const boost::asio::ip::address& peer,
                             const ForwardingHeaders& headers);

}  // namespace fw::server
