#include "redis_url.hpp"

#include <arpa/inet.h>

#include <cctype>
#include <charconv>
#include <fstream>

#include "log_text.hpp"
#include "percent_decoding.hpp"

namespace fw::server {
namespace {

constexpr std::string_view scheme = "redis://";
constexpr std::string_view expected_form =
    "expected redis://HOST[:PORT][/DB], e.g. redis://127.0.0.1:6379/0 (IPv6: redis://[::1]:6379; "
    "a password: redis://:PASSWORD@HOST, or redis://USER@HOST with --redis-password-file)";

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  return true;
}

// The URL as an error may show it: credentials hidden, control bytes and
// length bounded (it may come from a config file anyone could have typed).
std::string shown(std::string_view url) {
  std::string text(url);
  const auto at = text.rfind('@');
  if (starts_with_ignoring_case(text, scheme) && at != std::string::npos && at >= scheme.size())
    text = std::string(scheme) + "***" + text.substr(at);
  return printable(text, 200);
}

bool all_digits(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text)
    if (c < '0' || c > '9') return false;
  return true;
}

template <typename Number>
bool parse_number(std::string_view text, Number& number) {
  if (!all_digits(text)) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  return ec == std::errc() && end == text.data() + text.size();
}

bool is_host_name(std::string_view host) {
  for (const char c : host)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.' && c != '_') return false;
  return true;
}

}  // namespace

std::optional<RedisAddress> parse_redis_url(std::string_view url, std::string& error) {
  const auto fail = [&](const std::string& why) {
    error = "bad Redis URL '" + shown(url) + "': " + why + "; " + std::string(expected_form);
    return std::nullopt;
  };
  if (starts_with_ignoring_case(url, "rediss://"))
    return fail("TLS (rediss://) is not supported; reach Redis over a private network with redis://");
  if (starts_with_ignoring_case(url, "unix:") || starts_with_ignoring_case(url, "redis+unix:"))
    return fail("Unix sockets are not supported; use a TCP address");
  if (!starts_with_ignoring_case(url, scheme)) return fail("it must start with redis://");
  std::string_view rest = url.substr(scheme.size());
  if (rest.find_first_of("?#") != std::string_view::npos)
    return fail("options after '?' or '#' are not supported");

  RedisAddress address;
  // The user part ends at the last '@', so that a password with an
  // unencoded '@' or '/' in it still reads as one.
  if (const auto at = rest.rfind('@'); at != std::string_view::npos) {
    const std::string_view user_part = rest.substr(0, at);
    rest = rest.substr(at + 1);
    // USER alone: the password comes from --redis-password-file.
    const auto colon = user_part.find(':');
    if (colon == 0 && user_part.size() == 1) return fail("the password after ':' is empty");
    if (user_part.empty()) return fail("the part before '@' must be USER, :PASSWORD or USER:PASSWORD");
    const auto username = percent_decoded(user_part.substr(0, colon));
    const auto password =
        colon == std::string_view::npos ? std::optional<std::string>("") : percent_decoded(user_part.substr(colon + 1));
    if (!username || !password) return fail("a '%' in the user or password must start a %XX escape");
    if (colon != std::string_view::npos && password->empty()) return fail("the password after ':' is empty");
    address.username = *username;
    address.password = *password;
  }

  const auto slash = rest.find('/');
  const std::string_view host_port = rest.substr(0, slash);
  const std::string_view path = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);

  std::string_view port_text;
  bool has_port = false;
  if (!host_port.empty() && host_port.front() == '[') {
    const auto close = host_port.find(']');
    if (close == std::string_view::npos) return fail("an IPv6 address opened with '[' has no ']'");
    address.host = std::string(host_port.substr(1, close - 1));
    in6_addr ignored{};
    if (::inet_pton(AF_INET6, address.host.c_str(), &ignored) != 1)
      return fail(std::string("'") + printable(address.host, 60) + "' in brackets is not an IPv6 address");
    const std::string_view after = host_port.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') return fail("only ':PORT' may follow the ']' of an IPv6 address");
      port_text = after.substr(1);
      has_port = true;
    }
  } else {
    const auto colon = host_port.find(':');
    if (colon != std::string_view::npos && host_port.find(':', colon + 1) != std::string_view::npos)
      return fail("an IPv6 address goes in brackets, e.g. redis://[::1]:6379");
    address.host = std::string(host_port.substr(0, colon));
    if (colon != std::string_view::npos) {
      port_text = host_port.substr(colon + 1);
      has_port = true;
    }
    if (address.host.empty()) return fail("there is no host");
    if (!is_host_name(address.host))
      return fail(std::string("the host '") + printable(address.host, 60) +
                  "' has characters no host name has (letters, digits, '-', '.' and '_')");
  }
  if (address.host.empty()) return fail("there is no host");

  if (has_port) {
    unsigned port = 0;
    if (!parse_number(port_text, port) || port == 0 || port > 65535)
      return fail(std::string("the port must be a number from 1 to 65535, not '") + printable(port_text, 20) +
                  "'");
    address.port = static_cast<std::uint16_t>(port);
  }

  if (!path.empty()) {
    int db = 0;
    if (!parse_number(path, db))
      return fail(std::string("the database after '/' must be a number from 0 up (Redis has 0 to 15 unless ") +
                  "configured otherwise), not '" + printable(path, 20) + "'");
    address.db = db;
  }
  return address;
}

std::string to_string(const RedisAddress& address) {
  const bool ipv6 = address.host.find(':') != std::string::npos;
  std::string text = "redis://";
  if (ipv6) text.push_back('[');
  text.append(address.host);
  if (ipv6) text.push_back(']');
  text.append(":").append(std::to_string(address.port)).append("/").append(std::to_string(address.db));
  return text;
}

std::optional<std::string> read_redis_password_file(const std::string& path, std::string& error) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    error = "cannot read the Redis password file " + printable(path, 200) + ": check its path and that this user may read it";
    return std::nullopt;
  }
  std::string password;
  std::getline(file, password);
  if (!password.empty() && password.back() == '\r') password.pop_back();
  if (password.empty()) {
    error = "the Redis password file " + printable(path, 200) + " is empty: its first line is the password";
    return std::nullopt;
  }
  return password;
}

}  // namespace fw::server
