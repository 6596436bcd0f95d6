#include "server_url.hpp"

#include <charconv>

namespace fw::client {
namespace {

constexpr const char* kExamples = "; a server URL looks like ws://127.0.0.1:8080/ or tcp://127.0.0.1:8081";

bool valid_port(const std::string& port) {
  int value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  return ec == std::errc() && end == port.data() + port.size() && value >= 1 && value <= 65535;
}

}  // namespace

bool parse_server_url(const std::string& text, ServerUrl& url, std::string& error) {
  ServerUrl parsed;
  std::string rest;
  if (text.rfind("ws://", 0) == 0) {
    parsed.scheme = ServerUrl::Scheme::websocket;
    rest = text.substr(5);
  } else if (text.rfind("tcp://", 0) == 0) {
    parsed.scheme = ServerUrl::Scheme::tcp;
    rest = text.substr(6);
  } else if (text.rfind("wss://", 0) == 0 || text.rfind("http", 0) == 0) {
    error = "'" + text + "': only ws:// and tcp:// are supported (no TLS in this client)" + kExamples;
    return false;
  } else {
    error = "'" + text + "' is not a server URL" + kExamples;
    return false;
  }
  const auto slash = rest.find('/');
  std::string authority = rest.substr(0, slash);
  if (slash != std::string::npos) {
    if (parsed.scheme == ServerUrl::Scheme::tcp && slash + 1 != rest.size()) {
      error = "'" + text + "': a tcp:// URL has no path" + kExamples;
      return false;
    }
    parsed.path = rest.substr(slash);
  }
  // [v6]:port or host:port
  std::string host, port;
  if (!authority.empty() && authority.front() == '[') {
    const auto close = authority.find(']');
    if (close == std::string::npos || close + 1 >= authority.size() || authority[close + 1] != ':') {
      error = "'" + text + "': an IPv6 address needs a port, as in ws://[::1]:8080/";
      return false;
    }
    host = authority.substr(1, close - 1);
    port = authority.substr(close + 2);
  } else {
    const auto colon = authority.rfind(':');
    if (colon == std::string::npos) {
      error = "'" + text + "' has no port" + kExamples;
      return false;
    }
    host = authority.substr(0, colon);
    port = authority.substr(colon + 1);
  }
  if (host.empty() || !valid_port(port)) {
    error = "'" + text + "': the host or the port (1..65535) is missing or wrong" + kExamples;
    return false;
  }
  parsed.host = host;
  parsed.port = port;
  parsed.text = text;
  url = parsed;
  return true;
}

}  // namespace fw::client
