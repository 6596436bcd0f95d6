#pragma once
// Where a cluster node finds Redis: "redis://HOST[:PORT][/DB]", as given to
// `serve --redis`. A password (Redis' requirepass, or a user of its ACL)
// may ride in the URL's user part: "redis://:PASSWORD@HOST" or
// "redis://USER:PASSWORD@HOST", percent-encoded where it needs to be, or
// come from a file (--redis-password-file), the URL naming the user alone
// ("redis://USER@HOST") or none.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fw::server {

struct RedisAddress {
  std::string host;  ///< a name, an IPv4 address, or an IPv6 address (no brackets)
  std::uint16_t port = 6379;
  int db = 0;
  std::string username;  ///< empty: AUTH with the password alone (requirepass)
  std::string password;  ///< empty: no AUTH
};

/// "redis://HOST[:PORT][/DB]" (IPv6 host in brackets, e.g. redis://[::1]:6379/2).
/// nullopt and `error` saying what was wrong and the expected form; the
/// error never repeats a password.
std::optional<RedisAddress> parse_redis_url(std::string_view url, std::string& error);

/// The password in the file at `path` (--redis-password-file): its first
/// line, so that it stays out of the command line and the environment.
/// nullopt and `error` (naming the file, never its content) when the file
/// cannot be read or its first line is empty.
std::optional<std::string> read_redis_password_file(const std::string& path, std::string& error);

/// For logs: "redis://host:port/db", never the credentials.
std::string to_string(const RedisAddress& address);

}  // namespace fw::server
