#include "invite_link.hpp"

#include <cstdio>

namespace fw::server {
namespace {

// RFC 3986's unreserved characters stay; every other byte (UTF-8 of a name
// included) is percent-encoded, which URLSearchParams decodes.
std::string percent_encode(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    const bool unreserved = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                            c == '-' || c == '_' || c == '.' || c == '~';
    if (unreserved) {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

}  // namespace

std::optional<std::string> invite_link(const std::string& base_url, const std::string& room,
                                       const std::string& name, const std::string& token, std::string& error) {
  const bool http = base_url.rfind("http://", 0) == 0 || base_url.rfind("https://", 0) == 0;
  const std::size_t host = base_url.find("://") + 3;
  if (!http || base_url.size() <= host || base_url.find_first_of("?# ") != std::string::npos) {
    error = "'" + base_url + "' is not the server's address: give it as http://HOST:PORT/ (or https://...), "
            "without a query";
    return std::nullopt;
  }
  // The lobby is the server's start page: a base without a path gets "/".
  std::string link = base_url;
  if (link.find('/', host) == std::string::npos) link += '/';
  link += "?room=" + percent_encode(room);
  if (!name.empty()) link += "&name=" + percent_encode(name);
  link += "&token=" + percent_encode(token);
  return link;
}

}  // namespace fw::server
