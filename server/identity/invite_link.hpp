#pragma once
// The link that invites a person into a room of a server that needs join
// tokens: the lobby's address with the room, the name and the token in its
// query, which the lobby (web/lobby/invite.js) reads and passes on.
#include <optional>
#include <string>

namespace fw::server {

/// `base_url` (the server's public address, http:// or https://) with
/// `?room=R[&name=N]&token=T`, each value percent-encoded. nullopt and
/// `error` when the base is not an http(s) URL without a query.
std::optional<std::string> invite_link(const std::string& base_url, const std::string& room,
                                       const std::string& name, const std::string& token, std::string& error);

}  // namespace fw::server
