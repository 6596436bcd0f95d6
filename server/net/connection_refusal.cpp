#include "connection_refusal.hpp"

#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::server {

namespace {

bool share_taken(Abuse why) { return why == Abuse::address_connection_limit || why == Abuse::block_connection_limit; }

}  // namespace

std::string refusal_reason(Abuse why, std::size_t share, std::chrono::seconds retry_after) {
  const std::string again = "try again in " + std::to_string(retry_after.count()) + " s";
  if (why == Abuse::address_connection_limit)
    return "too many connections from your address (at most " + std::to_string(share) + " at once); close some, or " +
           again;
  if (why == Abuse::block_connection_limit)
    return "too many connections from your network (at most " + std::to_string(share) + " at once); " + again;
  return "the server has no room for more connections now; " + again;
}

std::string http_refusal(Abuse why, std::size_t share, std::chrono::seconds retry_after) {
  const std::string body = refusal_reason(why, share, retry_after) + "\n";
  return std::string(share_taken(why) ? "HTTP/1.1 429 Too Many Requests\r\n" : "HTTP/1.1 503 Service Unavailable\r\n") +
         "Server: facewire\r\n"
         "Content-Type: text/plain; charset=utf-8\r\n"
         "Retry-After: " + std::to_string(retry_after.count()) + "\r\n"
         "Connection: close\r\n"
         "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

std::string tcp_refusal(Abuse why, std::size_t share, std::chrono::seconds retry_after) {
  const auto code = share_taken(why) ? codec::CloseCode::rate_limited : codec::CloseCode::server_full;
  const codec::Closing closing{code, refusal_reason(why, share, retry_after).substr(0, codec::kMaxReasonBytes)};
  std::vector<std::uint8_t> message, framed;
  codec::write_message(closing, message);
  codec::write_tcp_frame(message, framed);
  return {framed.begin(), framed.end()};
}

}  // namespace fw::server
