#include "server_list.hpp"

#include <algorithm>

namespace fw::client {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "server 2 of 3" when there are several, so that the person finds the one.
std::string which(std::size_t index, std::size_t count) {
  return count > 1 ? "server " + std::to_string(index + 1) + " of " + std::to_string(count) + ": " : "";
}

}  // namespace

std::vector<std::string> split_at_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const auto comma = text.find(',', start);
    parts.push_back(trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

bool parse_server_list(const std::string& text, std::vector<ServerUrl>& servers, std::string& error) {
  const std::vector<std::string> parts = split_at_commas(text);
  if (parts.size() > kMaxServers) {
    error = "at most " + std::to_string(kMaxServers) + " server URLs, not " + std::to_string(parts.size());
    return false;
  }
  std::vector<ServerUrl> parsed;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].empty()) {
      error = parts.size() > 1 ? which(i, parts.size()) +
                                     "nothing between the commas; list servers as ws://a:8080/,ws://b:8080/"
                               : "no server URL; a server URL looks like ws://127.0.0.1:8080/ or tcp://127.0.0.1:8081";
      return false;
    }
    ServerUrl url;
    if (!parse_server_url(parts[i], url, error)) {
      error = which(i, parts.size()) + error;
      return false;
    }
    const bool twice = std::any_of(parsed.begin(), parsed.end(), [&](const ServerUrl& earlier) {
      return earlier.scheme == url.scheme && earlier.host == url.host && earlier.port == url.port;
    });
    if (twice) {
      error = which(i, parts.size()) + "'" + parts[i] + "' is listed twice; name each server once";
      return false;
    }
    parsed.push_back(std::move(url));
  }
  servers = std::move(parsed);
  return true;
}

}  // namespace fw::client
