#include "rest_api.hpp"

#include <nlohmann/json.hpp>

#include "api_access.hpp"
#include "avatar_deletion.hpp"
#include "room_registry.hpp"
#include "speech_languages.hpp"

namespace fw::server {

namespace http = boost::beast::http;

namespace {

Response plain(http::status status, const Request& request, std::string body) {
  return plain_response(status, request, std::move(body));
}

/// The answer for a stored avatar that cannot be served (avatar_store.hpp).
Response avatar_refusal(const Request& request, const AvatarLookup& lookup, const std::string& asset) {
  switch (lookup.status) {
    case AvatarStatus::being_prepared: {
      Response response = plain(http::status::service_unavailable, request, lookup.message + "\n");
      response.set(http::field::retry_after, "5");
      return response;
    }
    case AvatarStatus::out_of_date:
    case AvatarStatus::damaged: return plain(http::status::gone, request, lookup.message + " (POST /api/avatars)\n");
    case AvatarStatus::deleted: return plain(http::status::not_found, request, lookup.message + "\n");
    default:
      return plain(http::status::not_found, request,
                   "no avatar package '" + asset.substr(0, 64) + "'; upload one with POST /api/avatars\n");
  }
}

/// GET /api/packages/ID[?quality=preview]: the avatar's current package. Its
/// ETag is the package's content hash: the id stays when the server prepares
/// the avatar again, so caches revalidate.
Response package_response(const ApiServices& services, const Request& request, const std::string& asset,
                          bool preview) {
  const AvatarLookup lookup = services.store.lookup(asset);
  if (!lookup.avatar) return avatar_refusal(request, lookup, asset);
  const StoredAvatar& avatar = *lookup.avatar;
  const auto& bytes = preview ? *avatar.preview : *avatar.full;
  const std::string etag = "\"" + avatar.version + (preview ? "p" : "") + "\"";
  Response response{request[http::field::if_none_match] == etag ? http::status::not_modified : http::status::ok,
                    request.version()};
  response.set(http::field::server, "facewire");
  response.set(http::field::etag, etag);
  response.set(http::field::cache_control, "public, no-cache");
  response.keep_alive(request.keep_alive());
  if (response.result() != http::status::ok) return response;
  response.set(http::field::content_type, "application/x-facewire-avatar");
  if (request.method() == http::verb::head) {
    response.content_length(bytes.size());
  } else {
    response.body().assign(bytes.begin(), bytes.end());
    response.prepare_payload();
  }
  return response;
}

/// DELETE /api/avatars/ID with the avatar's key in X-Avatar-Key. Not behind
/// a join token: the key alone proves the upload, and a person must be able
/// to delete their photo after their invitation expired.
Response deletion_response(const ApiServices& services, const Request& request, const std::string& asset) {
  const std::string_view key(request["X-Avatar-Key"].data(), request["X-Avatar-Key"].size());
  const AvatarDeletion outcome =
      delete_avatar({services.store, services.rooms, services.own_faces, services.server_key}, asset, key);
  const std::string message = deletion_message(outcome, asset);
  switch (outcome) {
    case AvatarDeletion::deleted: return no_content_response(request);
    case AvatarDeletion::unknown: return plain(http::status::not_found, request, message + "\n");
    case AvatarDeletion::no_key:
    case AvatarDeletion::wrong_key:
      services.abuse.note(Abuse::face_not_yours, "api", "a deletion of avatar " + asset.substr(0, 64) +
                                                           (outcome == AvatarDeletion::no_key ? " without a key" : " with another key"));
      [[fallthrough]];
    default: return plain(http::status::forbidden, request, message + "\n");
  }
}

}  // namespace

Response json_response(http::status status, unsigned version, bool keep_alive, std::string body) {
  Response response{status, version};
  response.set(http::field::server, "facewire");
  response.set(http::field::content_type, "application/json");
  response.keep_alive(keep_alive);
  response.body() = std::move(body);
  response.prepare_payload();
  return response;
}

namespace {

/// GET /api/languages (PROTOCOL.md 8): what a hello may choose. The voices
/// installed do not change while the server runs, so it is made once. Open
/// without a token: it says nothing of rooms or people, and a page needs it
/// before its person joins.
const std::string& languages_json() {
  static const std::string body = [] {
    nlohmann::json languages = nlohmann::json::array();
    for (const SpeechLanguage& language : speech_languages())
      languages.push_back({{"code", language.code}, {"name", language.name}});
    return nlohmann::json{{"default", kDefaultSpeechLanguage}, {"languages", languages}}.dump() + "\n";
  }();
  return body;
}

}  // namespace

std::optional<Response> respond_to_api(const ApiServices& services, const Request& request) {
  const std::string_view target(request.target().data(), request.target().size());
  const std::string_view path = target.substr(0, target.find('?'));
  const std::string_view query = target.find('?') == std::string_view::npos ? "" : target.substr(target.find('?') + 1);
  if (request.method() == http::verb::delete_) {
    constexpr std::string_view kAvatars = "/api/avatars/";
    if (path.substr(0, kAvatars.size()) != kAvatars) return std::nullopt;
    return deletion_response(services, request, std::string(path.substr(kAvatars.size())));
  }
  if (path == "/readyz") {
    // A cluster node without Redis serves its own rooms, but a balancer
    // should send newcomers to nodes that can reach every room.
    const ServerState& state = services.state;
    const bool clustered = state.cluster_up.load();
    if (state.ready.load() && !state.draining.load() && clustered) return plain(http::status::ok, request, "ready\n");
    return plain(http::status::service_unavailable, request,
                 state.draining.load() ? "draining\n" : !state.ready.load() ? "starting\n" : "no Redis\n");
  }
  if (path == "/metrics") {
    if (Response refusal; !operator_access(services.config, request, refusal)) {
      services.abuse.note(Abuse::unauthorized, "metrics", "a request for /metrics without the operator's secret");
      return refusal;
    }
    Response response =
        plain(http::status::ok, request, services.metrics.render(services.physics_lod.share(), services.abuse));
    response.set(http::field::content_type, "text/plain; version=0.0.4; charset=utf-8");
    return response;
  }
  if (path == "/api/rooms") {
    Response refusal;
    const auto access = api_access(services.config, request, refusal);
    if (!access) return refusal;
    nlohmann::json rooms = nlohmann::json::array();
    for (const RoomSummary& room : services.rooms.list())
      // A token opens one room: a holder sees that room alone, not which
      // other rooms exist or who is in them.
      if (access->open || room.name == access->claims->room) rooms.push_back({{"name", room.name}, {"avatars", room.avatars}, {"persons", room.persons}});
    return json_response(http::status::ok, request.version(), request.keep_alive(),
                         nlohmann::json{{"rooms", rooms}}.dump() + "\n");
  }
  if (path == "/api/languages") return json_response(http::status::ok, request.version(), request.keep_alive(), languages_json());
  constexpr std::string_view kPackages = "/api/packages/";
  if (path.substr(0, kPackages.size()) == kPackages)
    return package_response(services, request, std::string(path.substr(kPackages.size())), query == "quality=preview");
  return std::nullopt;
}

}  // namespace fw::server
