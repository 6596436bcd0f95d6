#include "connection_refusal.hpp"

#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::server {

namespace {

bool address_share_taken(Abuse why) { return why == Abuse::address_connection_limit; }

}  // namespace

std::string refusal_reason(Abuse why, std::size_t per_address) {
  if (address_share_taken(why))
    return "too many connections from your address (at most " + std::to_string(per_address) +
           " at once); close some and try again";
  return "the server has no room for more connections now; try again in a minute";
}

std::string http_refusal(Abuse why, std::size_t per_address) {
  const std::string body = refusal_reason(why, per_address) + "\n";
  const bool address = address_share_taken(why);
  return std::string(address ? "HTTP/1.1 429 Too Many Requests\r\n" : "HTTP/1.1 503 Service Unavailable\r\n") +
         "Server: facewire\r\n"
         "Content-Type: text/plain; charset=utf-8\r\n"
         "Retry-After: " + (address ? "10" : "60") + "\r\n"
         "Connection: close\r\n"
         "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

std::string tcp_refusal(Abuse why, std::size_t per_address) {
  const auto code = address_share_taken(why) ? codec::CloseCode::rate_limited : codec::CloseCode::server_full;
  const codec::Closing closing{code, refusal_reason(why, per_address).substr(0, codec::kMaxReasonBytes)};
  std::vector<std::uint8_t> message, framed;
  codec::write_message(closing, message);
  codec::write_tcp_frame(message, framed);
  return {framed.begin(), framed.end()};
}

}  // namespace fw::server
