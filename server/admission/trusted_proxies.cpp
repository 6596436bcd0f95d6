#include "trusted_proxies.hpp"

#include <algorithm>
#include <cctype>

#include "log_text.hpp"

namespace fw::server {

namespace ip = boost::asio::ip;

namespace {

/// An IPv4 address mapped into IPv6 as the IPv4 address; others as they are.
ip::address unmapped(const ip::address& address) {
  if (address.is_v6() && address.to_v6().is_v4_mapped())
    return ip::make_address_v4(ip::v4_mapped, address.to_v6());
  return address;
}

unsigned width(const ip::address& address) { return address.is_v4() ? 32 : 128; }

/// `address` with every bit past the first `prefix` cleared.
ip::address network_of(const ip::address& address, unsigned prefix) {
  if (address.is_v4()) {
    const std::uint32_t mask = prefix == 0 ? 0 : ~std::uint32_t{0} << (32 - prefix);
    return ip::address_v4(address.to_v4().to_uint() & mask);
  }
  ip::address_v6::bytes_type bytes = address.to_v6().to_bytes();
  for (unsigned bit = prefix; bit < 128; ++bit) bytes[bit / 8] &= static_cast<std::uint8_t>(~(0x80u >> (bit % 8)));
  return ip::address_v6(bytes);
}

std::string_view trimmed(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

bool is_port(std::string_view text) {
  return !text.empty() && text.size() <= 5 &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// One hop's address as proxies write it: "192.0.2.1", "192.0.2.1:4711",
/// "2001:db8::1", "[2001:db8::1]" or "[2001:db8::1]:4711".
std::optional<ip::address> parse_node(std::string_view text) {
  boost::system::error_code ec;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    const std::string_view rest = text.substr(close + 1);
    if (!rest.empty() && (rest.front() != ':' || !is_port(rest.substr(1)))) return std::nullopt;
    const ip::address_v6 v6 = ip::make_address_v6(std::string(text.substr(1, close - 1)), ec);
    if (ec) return std::nullopt;
    return unmapped(v6);
  }
  if (std::count(text.begin(), text.end(), ':') == 1) {  // IPv4 and a port
    const auto colon = text.find(':');
    if (!is_port(text.substr(colon + 1))) return std::nullopt;
    const ip::address_v4 v4 = ip::make_address_v4(std::string(text.substr(0, colon)), ec);
    if (ec) return std::nullopt;
    return v4;
  }
  const ip::address address = ip::make_address(std::string(text), ec);
  if (ec) return std::nullopt;
  return unmapped(address);
}

/// Each X-Forwarded-For entry, leftmost first; empty list elements are none.
std::vector<std::string> x_forwarded_for_hops(const std::vector<std::string_view>& lines) {
  std::vector<std::string> hops;
  for (std::string_view line : lines) {
    for (;;) {
      const auto comma = line.find(',');
      const std::string_view entry = trimmed(line.substr(0, comma));
      if (!entry.empty()) hops.emplace_back(entry);
      if (comma == std::string_view::npos) break;
      line.remove_prefix(comma + 1);
    }
  }
  return hops;
}

/// A quoted-string's content (RFC 9110 5.6.4), or the token as it is.
std::string unquoted(std::string_view value) {
  if (value.size() < 2 || value.front() != '"' || value.back() != '"') return std::string(value);
  std::string out;
  for (std::size_t i = 1; i + 1 < value.size(); ++i) {
    if (value[i] == '\\' && i + 2 < value.size()) ++i;
    out += value[i];
  }
  return out;
}

bool is_for_key(std::string_view key) {
  return key.size() == 3 && std::tolower(static_cast<unsigned char>(key[0])) == 'f' &&
         std::tolower(static_cast<unsigned char>(key[1])) == 'o' &&
         std::tolower(static_cast<unsigned char>(key[2])) == 'r';
}

/// The for= of one Forwarded element ("for=192.0.2.1;proto=https"), or
/// nullopt when it has none.
std::optional<std::string> forwarded_for(std::string_view element) {
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= element.size(); ++i) {
    if (i < element.size()) {
      const char c = element[i];
      if (quoted && c == '\\') {
        ++i;
        continue;
      }
      if (c == '"') quoted = !quoted;
      if (quoted || c != ';') continue;
    }
    const std::string_view pair = element.substr(start, i - start);
    start = i + 1;
    const auto equals = pair.find('=');
    if (equals != std::string_view::npos && is_for_key(trimmed(pair.substr(0, equals))))
      return unquoted(trimmed(pair.substr(equals + 1)));
  }
  return std::nullopt;
}

/// Each Forwarded element's for= (RFC 7239), leftmost first; an element
/// without one is an empty hop, which names no address.
std::vector<std::string> forwarded_hops(const std::vector<std::string_view>& lines) {
  std::vector<std::string> hops;
  for (const std::string_view line : lines) {
    bool quoted = false;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= line.size(); ++i) {
      if (i < line.size()) {
        const char c = line[i];
        if (quoted && c == '\\') {
          ++i;
          continue;
        }
        if (c == '"') quoted = !quoted;
        if (quoted || c != ',') continue;
      }
      const std::string_view element = trimmed(line.substr(start, i - start));
      start = i + 1;
      if (!element.empty()) hops.push_back(forwarded_for(element).value_or(""));
    }
  }
  return hops;
}

ClientAddress malformed(const ip::address& peer, std::string problem) {
  return {peer, ClientAddress::Source::malformed, std::move(problem)};
}

/// The rightmost hop that is not a trusted proxy (the leftmost if all are).
ClientAddress rightmost_untrusted(const TrustedProxies& proxies, const ip::address& peer,
                                  const std::vector<std::string>& hops, std::string_view header) {
  if (hops.empty()) return malformed(peer, std::string(header) + " names no address");
  ip::address leftmost;
  for (auto hop = hops.rbegin(); hop != hops.rend(); ++hop) {
    const auto address = parse_node(*hop);
    if (!address)
      return malformed(peer, std::string(header) + ": '" + printable(*hop, 60) + "' is not an address");
    if (!proxies.contains(*address)) return {*address, ClientAddress::Source::forwarded, {}};
    leftmost = *address;
  }
  return {leftmost, ClientAddress::Source::forwarded, {}};
}

}  // namespace

bool AddressRange::contains(const ip::address& address) const {
  const ip::address candidate = unmapped(address);
  if (candidate.is_v4() != network.is_v4()) return false;
  return network_of(candidate, prefix) == network;
}

std::string AddressRange::to_string() const { return network.to_string() + "/" + std::to_string(prefix); }

std::optional<AddressRange> parse_address_range(std::string_view text, std::string& error) {
  const std::string_view range = trimmed(text);
  const std::string example = "write ADDRESS/PREFIX (10.0.0.0/8, fd00::/8) or one address (127.0.0.1)";
  if (range.empty()) {
    error = "an empty address range; " + example;
    return std::nullopt;
  }
  const auto slash = range.find('/');
  const std::string shown = printable(range, 60);
  boost::system::error_code ec;
  ip::address network = ip::make_address(std::string(range.substr(0, slash)), ec);
  if (ec) {
    error = "'" + shown + "' is not an address range: '" + printable(range.substr(0, slash), 60) +
            "' is no IPv4 or IPv6 address; " + example;
    return std::nullopt;
  }
  unsigned prefix = width(network);
  if (slash != std::string_view::npos) {
    const std::string_view digits = range.substr(slash + 1);
    if (digits.empty() || digits.size() > 3 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
        static_cast<unsigned>(std::stoul(std::string(digits))) > width(network)) {
      error = "'" + shown + "': the prefix length must be a number from 0 to " + std::to_string(width(network)) +
              " for an IPv" + (network.is_v4() ? "4" : "6") + " address";
      return std::nullopt;
    }
    prefix = static_cast<unsigned>(std::stoul(std::string(digits)));
  }
  if (network.is_v6() && network.to_v6().is_v4_mapped() && prefix >= 96) {
    network = unmapped(network);  // ::ffff:10.0.0.0/104 is 10.0.0.0/8
    prefix -= 96;
  }
  const AddressRange parsed{network_of(network, prefix), prefix};
  if (parsed.network != network) {
    error = "'" + shown + "' has bits set past its /" + std::to_string(prefix) + " prefix; write the network, " +
            parsed.to_string() + ", or " + network.to_string() + "/" + std::to_string(width(network)) +
            " for the one address";
    return std::nullopt;
  }
  return parsed;
}

bool TrustedProxies::add(std::string_view range, std::string& error) {
  const auto parsed = parse_address_range(range, error);
  if (!parsed) return false;
  ranges_.push_back(*parsed);
  return true;
}

bool TrustedProxies::contains(const ip::address& address) const {
  return std::any_of(ranges_.begin(), ranges_.end(), [&](const AddressRange& r) { return r.contains(address); });
}

ClientAddress client_address(const TrustedProxies& proxies, const ip::address& peer,
                             const ForwardingHeaders& headers) {
  if (!proxies.contains(peer)) return {peer, ClientAddress::Source::peer, {}};
  const ip::address direct = unmapped(peer);
  if (!headers.x_forwarded_for.empty())
    return rightmost_untrusted(proxies, direct, x_forwarded_for_hops(headers.x_forwarded_for), "X-Forwarded-For");
  if (!headers.forwarded.empty())
    return rightmost_untrusted(proxies, direct, forwarded_hops(headers.forwarded), "Forwarded");
  return {direct, ClientAddress::Source::peer, {}};
}

}  // namespace fw::server
