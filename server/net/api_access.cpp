#include "api_access.hpp"

#include <chrono>

#include <openssl/crypto.h>

#include "http_responses.hpp"

namespace fw::server {

namespace http = boost::beast::http;

namespace {

/// The value of `key` in a query string, percent-decoding not needed: a
/// token is base64url and dots.
std::string query_value(std::string_view query, std::string_view key) {
  while (!query.empty()) {
    const auto amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    if (pair.size() > key.size() && pair.substr(0, key.size()) == key && pair[key.size()] == '=')
      return std::string(pair.substr(key.size() + 1));
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return {};
}

std::string bearer(const Request& request) {
  const std::string_view value(request[http::field::authorization].data(), request[http::field::authorization].size());
  constexpr std::string_view kBearer = "Bearer ";
  return value.substr(0, kBearer.size()) == kBearer ? std::string(value.substr(kBearer.size())) : std::string();
}

Response unauthorized(const Request& request, const std::string& why) {
  Response response = error_response(http::status::unauthorized, request.version(), why);
  response.set(http::field::www_authenticate, "Bearer");
  return response;
}

}  // namespace

std::string request_token(const Request& request) {
  if (std::string token = bearer(request); !token.empty()) return token;
  const std::string_view target(request.target().data(), request.target().size());
  const auto question = target.find('?');
  return question == std::string_view::npos ? std::string() : query_value(target.substr(question + 1), "token");
}

std::optional<ApiAccess> api_access(const ServerConfig& config, const Request& request, Response& refusal) {
  if (config.auth_secret.empty()) return ApiAccess{};
  const auto now =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  std::string why;
  auto claims = verify_join_token(request_token(request), config.auth_secret, now, why);
  if (!claims) {
    refusal = unauthorized(request, why + " (send it as 'Authorization: Bearer TOKEN' or ?token=TOKEN)");
    return std::nullopt;
  }
  return ApiAccess{false, std::move(claims)};
}

bool operator_access(const ServerConfig& config, const Request& request, Response& refusal) {
  const std::string& secret = config.metrics_secret;
  if (secret.empty()) {
    if (config.auth_secret.empty()) return true;
    refusal = error_response(http::status::forbidden, request.version(),
                             "metrics are closed on a server with --auth-secret; start it with --metrics-secret S "
                             "and send 'Authorization: Bearer S'");
    return false;
  }
  const std::string presented = bearer(request);
  if (presented.size() == secret.size() && CRYPTO_memcmp(presented.data(), secret.data(), secret.size()) == 0)
    return true;
  refusal = unauthorized(request, "metrics need the operator's secret: 'Authorization: Bearer S' (--metrics-secret)");
  return false;
}

}  // namespace fw::server
