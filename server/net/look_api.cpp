#include "look_api.hpp"

#include <nlohmann/json.hpp>

#include "avatar_deletion.hpp"
#include "peer_address.hpp"
#include "percent_decoding.hpp"
#include "rest_api.hpp"
#include "script_check.hpp"

namespace fw::server {

namespace http = boost::beast::http;

namespace {

constexpr std::string_view kAvatars = "/api/avatars/";
constexpr std::string_view kLooks = "/looks";

/// What a look route names: the avatar, and the look (empty for the list).
struct LookTarget {
  std::string asset;
  std::string name;  ///< percent-decoded, not yet checked
  bool named = false;
};

std::optional<LookTarget> look_target(std::string_view target) {
  const std::string_view path = target.substr(0, target.find('?'));
  if (!path.starts_with(kAvatars)) return std::nullopt;
  const std::string_view rest = path.substr(kAvatars.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  LookTarget out{std::string(rest.substr(0, slash)), {}, false};
  const std::string_view tail = rest.substr(slash);
  if (tail == kLooks || tail == "/looks/") return out;
  if (!tail.starts_with("/looks/")) return std::nullopt;
  out.named = true;
  out.name = std::string(tail.substr(kLooks.size() + 1));
  return out;
}

/// The looks' answers end their text with a line break, as curl users expect.
Response plain(http::status status, const Request& request, const std::string& body) {
  return plain_response(status, request, body + "\n");
}

Response retry_later(const Request& request, double seconds, const std::string& whose) {
  const long wait = static_cast<long>(seconds) + 1;
  Response response = plain(http::status::too_many_requests, request,
                            "too many saved-look changes " + whose + "; try again in " + std::to_string(wait) + " s");
  response.set(http::field::retry_after, std::to_string(wait));
  return response;
}

nlohmann::json look_json(const SavedLook& look) {
  std::vector<std::string> kinds;
  playable_script(look.script, kinds);  // checked when saved; a room's bounds may have changed since
  return {{"name", look.name}, {"kinds", kinds}, {"bytes", look.script.size()}, {"script", look.script}};
}

Response list_response(const ApiServices& services, const Request& request, const std::string& asset) {
  nlohmann::json looks = nlohmann::json::array();
  for (const SavedLook& look : services.looks.list(asset)) looks.push_back(look_json(look));
  return json_response(http::status::ok, request.version(), request.keep_alive(),
                       nlohmann::json{{"looks", looks}, {"max", kMaxLooksPerAvatar}}.dump() + "\n");
}

Response save_response(const ApiServices& services, const Request& request, const std::string& asset,
                       const std::string& name) {
  if (request.body().size() > kMaxLookScriptBytes) return oversized_look(request.version(), request.body().size());
  std::vector<std::string> kinds;
  if (std::string error = playable_script(request.body(), kinds); !error.empty())
    return plain(http::status::unprocessable_entity, request, error);
  std::string why;
  switch (services.looks.put(asset, {name, request.body()}, why)) {
    case LookChange::done: break;
    case LookChange::full: return plain(http::status::conflict, request, why);
    default: return plain(http::status::service_unavailable, request, why);
  }
  return json_response(http::status::ok, request.version(), request.keep_alive(),
                       look_json({name, request.body()}).dump() + "\n");
}

Response deletion_response(const ApiServices& services, const Request& request, const std::string& asset,
                           const std::string& name) {
  std::string why;
  switch (services.looks.remove(asset, name, why)) {
    case LookChange::done: return no_content_response(request);
    case LookChange::unknown_look: return plain(http::status::not_found, request, why);
    default: return plain(http::status::service_unavailable, request, why);
  }
}

}  // namespace

bool is_look_route(std::string_view target) { return look_target(target).has_value(); }

bool is_look_save(http::verb method, std::string_view target) {
  const auto look = look_target(target);
  return method == http::verb::put && look && look->named;
}

Response oversized_look(unsigned version, std::size_t bytes) {
  return error_response(http::status::payload_too_large, version,
                        "the look's script is " + std::to_string(bytes) + " bytes; a saved look holds at most " +
                            std::to_string(kMaxLookScriptBytes) + " (what a room plays): shorten it");
}

std::optional<Response> respond_to_looks(const ApiServices& services, const Request& request,
                                         const std::string& peer) {
  const std::string_view target(request.target().data(), request.target().size());
  const auto look = look_target(target);
  if (!look) return std::nullopt;
  const http::verb method = request.method();
  if (look->named ? method != http::verb::put && method != http::verb::delete_ : method != http::verb::get) {
    Response refusal = plain(http::status::method_not_allowed, request,
                             look->named ? "a look is saved with PUT and deleted with DELETE"
                                         : "the looks are listed with GET; one is saved with PUT .../looks/NAME");
    refusal.set(http::field::allow, look->named ? "PUT, DELETE" : "GET");
    return refusal;
  }
  const std::string_view key(request["X-Avatar-Key"].data(), request["X-Avatar-Key"].size());
  const AvatarDeletion owner =
      check_avatar_owner({services.store, services.rooms, services.own_faces, services.server_key}, look->asset, key);
  switch (owner) {
    case AvatarDeletion::deleted: break;  // its owner
    case AvatarDeletion::unknown: return plain(http::status::not_found, request, deletion_message(owner, look->asset));
    case AvatarDeletion::server_face:
      return plain(http::status::forbidden, request,
                   "avatar " + look->asset.substr(0, 64) + " is one of the server's own faces: it keeps no looks");
    default:
      services.abuse.note(Abuse::face_not_yours, peer,
                          "saved looks of avatar " + look->asset.substr(0, 64) +
                              (owner == AvatarDeletion::no_key ? " without a key" : " with another key"));
      return plain(http::status::forbidden, request,
                   owner == AvatarDeletion::no_key
                       ? "saved looks take the avatar's key: send the 'key' its upload answered in an X-Avatar-Key "
                         "header"
                       : "that is not the key of avatar " + look->asset.substr(0, 64) +
                             ": only whoever uploaded it keeps looks with it");
  }
  if (!look->named) return list_response(services, request, look->asset);
  std::string name;
  const auto decoded = percent_decoded(look->name);
  if (!decoded) return plain(http::status::bad_request, request, "the look's name in the path is not percent-encoded");
  if (std::string why = normalize_look_name(*decoded, name); !why.empty())
    return plain(http::status::bad_request, request, why);
  // Each change is a durable write (and a Redis write in a cluster).
  if (const auto wait = services.addresses.take(AddressRate::look_save, address_key(peer)))
    return retry_later(request, *wait, "from your address");
  if (const auto wait = services.addresses.take(AddressRate::avatar_look_save, avatar_rate_key(look->asset)))
    return retry_later(request, *wait, "of this avatar");
  if (method == http::verb::delete_) return deletion_response(services, request, look->asset, name);
  return save_response(services, request, look->asset, name);
}

}  // namespace fw::server
