#pragma once
// The servers `facewire-client join` may use: one URL, or several separated
// by commas (`ws://a:8080/,ws://b:8080/`), the nodes of one community. The
// first that answers is used; when its link fails the session moves on to
// the next (failover_policy.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "server_url.hpp"

namespace fw::client {

/// More than a person would list; a longer list is a mistake (a pasted file?).
inline constexpr std::size_t kMaxServers = 16;

/// Splits `text` at commas (blanks around each URL are dropped) and reads
/// every URL with parse_server_url.
/// @return false and `error`, which names the URL that is wrong and why
bool parse_server_list(const std::string& text, std::vector<ServerUrl>& servers, std::string& error);

/// `text` split at commas, each part without the blanks around it (empty
/// parts kept, so that a caller can say where one is missing).
std::vector<std::string> split_at_commas(const std::string& text);

}  // namespace fw::client
