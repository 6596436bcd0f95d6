#pragma once
// What the saved-look tests do over HTTP and the room protocol, against a
// real server on loopback: upload a face of their own, save, list and
// delete its looks with a key, wear it in a room and play a look by name
// (PROTOCOL.md 8.2, command kind 6). Shared by the single server's tests
// and the cluster's.
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "demo_faces.hpp"
#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"

namespace fw::test {

using namespace std::chrono_literals;

struct OwnedAvatar {
  std::string asset, key;
};

/// A face of its own (`seed` picks it) uploaded from `from`; empty when the
/// upload was refused.
inline OwnedAvatar upload_own_face(const std::string& from, int port, std::uint32_t seed) {
  const auto bytes = server::make_demo_package(seed);
  const std::string body(bytes.begin(), bytes.end());
  const HttpReply reply =
      http_from(from, port,
                "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\nContent-Type: "
                "application/x-facewire-avatar\r\nContent-Length: " +
                    std::to_string(body.size()) + "\r\n\r\n" + body,
                60s);
  const auto answer = nlohmann::json::parse(reply.body, nullptr, false);
  if (reply.status != 201 || !answer.is_object() || !answer.contains("key")) return {};
  return {answer["asset"], answer["key"]};
}

/// `name` as a path segment: spaces and anything past ASCII percent-encoded
/// (a name written encoded already keeps its escapes).
inline std::string path_segment(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > ' ' && byte < 0x7F && c != '/' && c != '?' && c != '#') {
      out += c;
    } else {
      constexpr char kHex[] = "0123456789ABCDEF";
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

/// METHOD /api/avatars/ASSET/looks[/NAME] from `from`, with `key` unless empty.
inline HttpReply look_request(const std::string& from, int port, const std::string& method, const std::string& asset,
                              const std::string& name, const std::string& key, const std::string& body = "") {
  const std::string path = "/api/avatars/" + asset + "/looks" + (name.empty() ? "" : "/" + path_segment(name));
  return http_from(from, port,
                   method + " " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" +
                       (key.empty() ? "" : "X-Avatar-Key: " + key + "\r\n") +
                       (method == "PUT" ? "Content-Type: text/plain\r\nContent-Length: " +
                                              std::to_string(body.size()) + "\r\n"
                                        : "") +
                       "\r\n" + body);
}

inline HttpReply save_look(const std::string& from, int port, const OwnedAvatar& avatar, const std::string& name,
                           const std::string& script) {
  return look_request(from, port, "PUT", avatar.asset, name, avatar.key, script);
}

/// A hello from `from` to `room` wearing `avatar`, answered by a welcome or a closing.
inline std::unique_ptr<RoomTestClient> wear_in(int tcp_port, const std::string& from, const std::string& room,
                                               const std::string& name, const OwnedAvatar& avatar) {
  auto client = std::make_unique<RoomTestClient>(RoomTestClient::Transport::tcp, tcp_port, from);
  codec::Hello hello;
  hello.room = room;
  hello.name = name;
  hello.avatar = avatar.asset;
  hello.avatar_key = avatar.key;
  client->send_message(hello);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 10s);
  return client;
}

/// Command kind 6 for `name`, and its answer (nullopt: none within 10 s).
inline std::optional<std::string> play_look(RoomTestClient& client, std::uint32_t request_id, const std::string& name) {
  codec::Command play;
  play.request_id = request_id;
  play.kind = codec::Command::Kind::play_look;
  play.sentence = name;
  const std::size_t before = client.results.size();
  client.send_message(play);
  std::optional<std::string> answer;
  client.pump_until(
      [&] {
        for (std::size_t i = before; i < client.results.size(); ++i)
          if (client.results[i].request_id == request_id) answer = client.results[i].error;
        return answer.has_value();
      },
      10s);
  return answer;
}

/// The largest blush, over the colour regions, of `avatar` as `client` decodes it now.
inline float largest_blush(const RoomTestClient& client, std::uint32_t avatar) {
  const codec::Decoder* decoder = client.decoder.avatar(avatar);
  if (!decoder) return 0;
  float largest = 0;
  for (const float blush : decoder->face().blush) largest = std::max(largest, blush);
  return largest;
}

/// Pumps `client` until `avatar`'s largest blush passes `level`, for
/// `timeout` at most; the blush then (at most `level` when it never passed).
inline float blush_within(RoomTestClient& client, std::uint32_t avatar, float level,
                          std::chrono::milliseconds timeout) {
  float blush = 0;
  client.pump_until([&] { return (blush = largest_blush(client, avatar)) > level; }, timeout);
  return blush;
}

/// A vascular episode, as the face lab's example (blushing.fws) reduced to one stage.
inline const std::string kBlushLook =
    "[emotion flushed\n  [stage1 duration 100 [expression flush intensity 1.0]]]\n"
    "[expression flush\n  [mpca cheeks intensity 1.0]\n  [mpca forehead intensity 0.8]]\n";

}  // namespace fw::test
