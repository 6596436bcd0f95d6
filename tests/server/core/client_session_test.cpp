// ClientSession, the protocol side of a room connection, driven through the
// in-memory transport: the hello and its checks (names, versions, avatars,
// join tokens), every limit on what a peer sends (server_limits.hpp), the
// time-outs, and the bounded queue in front of a peer that does not read.
#include "client_session.hpp"

#include <chrono>
#include <future>
#include <map>

#include <boost/asio/post.hpp>
#include <fw/codec/byte_writer.hpp>
#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "join_token.hpp"
#include "server_limits.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::HelloOptions;
using test::InMemoryServer;
using namespace std::chrono_literals;

ServerConfig config_with(const std::function<void(ServerConfig&)>& change) {
  ServerConfig config = InMemoryServer::test_config();
  change(config);
  return config;
}

std::int64_t unix_now() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// The code of the closing message `peer` got once the server ended its connection.
std::optional<CloseCode> closed_with(test::InMemoryPeer& peer) {
  if (!peer.read_until_closed()) return std::nullopt;
  peer.read();
  if (!peer.closing) return std::nullopt;
  return peer.closing->code;
}

/// A hello whose room or name is past the codec's limits, which the codec's
/// own writer refuses to write (it asserts): the bytes are laid out by hand
/// as server/PROTOCOL.md gives them, the fields before the room taken from
/// a hello the writer did write.
std::vector<std::uint8_t> oversized_hello(const std::string& room, const std::string& name) {
  std::vector<std::uint8_t> head;
  codec::write_message(codec::Hello{}, head);  // type, version, flags, max_bps 0, then seven empty strings
  std::vector<std::uint8_t> bytes(head.begin(), head.end() - 7);
  codec::ByteWriter w(bytes);
  for (const std::string& text : {room, name}) {
    w.varint(static_cast<std::uint32_t>(text.size()));
    w.bytes(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  }
  w.varint(0);  // no avatar
  w.varint(0);  // no token
  w.varint(0);  // no avatar key
  w.varint(0);  // no resume key
  w.varint(0);  // the server's default language
  return bytes;
}

/// The closing message a connection gets for `hello`.
std::optional<CloseCode> closing_for(InMemoryServer& server, std::vector<std::uint8_t> hello) {
  auto peer = server.connect();
  peer->send_bytes(std::move(hello));
  return closed_with(*peer);
}

// --- the hello ---------------------------------------------------------------

TEST(ClientSession, AHelloIsWelcomedAndTheStreamHeaderFollows) {
  InMemoryServer server;
  auto peer = server.join("room-1", "Ann");
  ASSERT_TRUE(peer->welcome) << (peer->closing ? peer->closing->reason : "no answer");
  EXPECT_EQ(peer->welcome->room, "room-1");
  EXPECT_EQ(peer->welcome->tick_hz, 30);
  ASSERT_EQ(peer->welcome->avatars.size(), 1u);
  EXPECT_EQ(peer->welcome->avatars[0].id, peer->welcome->you);
  EXPECT_EQ(peer->welcome->avatars[0].name, "Ann");
  EXPECT_TRUE(peer->read_until([&] { return peer->stream_header; }));
  EXPECT_TRUE(peer->errors.empty()) << peer->errors.front();
}

TEST(ClientSession, TheBudgetIsTheClientsCappedByTheServerOrTheDefault) {
  InMemoryServer server(config_with([](ServerConfig& c) {
    c.default_client_bps = 32000;
    c.max_client_bps = 200000;
  }));
  auto quiet = server.join("r", "Quiet");
  auto greedy = server.join("r", "Greedy", {.max_bps = 5'000'000});
  auto modest = server.join("r", "Modest", {.max_bps = 20000});
  ASSERT_TRUE(quiet->welcome && greedy->welcome && modest->welcome);
  EXPECT_EQ(quiet->welcome->max_bps, 32000u) << "0 asks for the server's default";
  EXPECT_EQ(greedy->welcome->max_bps, 200000u) << "capped at --max-client-bps";
  EXPECT_EQ(modest->welcome->max_bps, 20000u);
}

TEST(ClientSession, AFirstMessageThatIsNoHelloIsAProtocolError) {
  InMemoryServer server;
  auto peer = server.connect();
  peer->send(codec::Chat{0, "hi"});
  EXPECT_EQ(closed_with(*peer), CloseCode::protocol_error);
  EXPECT_NE(peer->closing->reason.find("the first message must be a hello"), std::string::npos);
  EXPECT_EQ(server.core().metrics().protocol_errors.load(), 1u);
}

TEST(ClientSession, AnotherProtocolVersionIsRefusedNamingOurs) {
  InMemoryServer server;
  auto peer = server.connect();
  codec::Hello hello;
  hello.room = "r";
  hello.name = "Ann";
  std::vector<std::uint8_t> bytes;
  codec::write_message(hello, bytes);
  bytes[1] = 6;  // protocol_version, u16 little-endian after the type byte: one this server does not speak
  peer->send_bytes(bytes);
  EXPECT_EQ(closed_with(*peer), CloseCode::unsupported_version);
  EXPECT_NE(peer->closing->reason.find("versions 3 to 5"), std::string::npos) << peer->closing->reason;
}

TEST(ClientSession, RoomNamesAreLettersDigitsAndFewMarks) {
  InMemoryServer server;
  auto spaces = server.join("no spaces allowed", "Ann");
  ASSERT_TRUE(spaces->closing);
  EXPECT_EQ(spaces->closing->code, CloseCode::bad_request);
  EXPECT_NE(spaces->closing->reason.find("room names are 1 to 64 characters"), std::string::npos);
  EXPECT_EQ(closing_for(server, oversized_hello(std::string(codec::kMaxRoomNameBytes + 1, 'a'), "Ann")),
            CloseCode::protocol_error)
      << "a hello past the codec's limit is malformed";
  auto longest = server.join(std::string(codec::kMaxRoomNameBytes, 'a'), "Ann");
  EXPECT_TRUE(longest->welcome);
  EXPECT_EQ(server.core().metrics().rejected_joins.load(), 1u)
      << "the bad name; the malformed hello is a protocol error";
}

TEST(ClientSession, DisplayNamesAreOneTo32Bytes) {
  InMemoryServer server;
  auto empty = server.join("r", "");
  ASSERT_TRUE(empty->closing);
  EXPECT_EQ(empty->closing->code, CloseCode::bad_request);
  EXPECT_NE(empty->closing->reason.find("at least one visible character"), std::string::npos) << empty->closing->reason;
  EXPECT_EQ(closing_for(server, oversized_hello("r", std::string(codec::kMaxDisplayNameBytes + 1, 'n'))),
            CloseCode::protocol_error);
  auto longest = server.join("r", std::string(codec::kMaxDisplayNameBytes, 'n'));
  EXPECT_TRUE(longest->welcome);
}

TEST(ClientSession, AnUnknownAvatarIsRefusedWithWhatToDo) {
  InMemoryServer server;
  auto peer = server.join("r", "Ann", {.avatar = std::string(32, '0')});
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
  EXPECT_NE(peer->closing->reason.find("upload it first"), std::string::npos);
}

TEST(ClientSession, AnAvatarKeyWithoutItsAvatarIsRefusedNotIgnored) {
  InMemoryServer server;
  auto peer = server.join("r", "Ann", {.avatar_key = std::string("k3y-_AZaz09k3y-_AZaz09")});
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
  EXPECT_NE(peer->closing->reason.find("without the avatar"), std::string::npos) << peer->closing->reason;
  EXPECT_EQ(server.core().abuse().count(Abuse::bad_hello), 1u);
}

TEST(ClientSession, EveryRefusalAndClosingForALimitIsCountedByKind) {
  InMemoryServer server;
  auto garbage = server.connect();
  garbage->send(codec::Chat{0, "hi"});
  EXPECT_EQ(closed_with(*garbage), CloseCode::protocol_error);
  EXPECT_EQ(server.core().abuse().count(Abuse::protocol_violation), 1u);
  EXPECT_EQ(closing_for(server, oversized_hello("no room!", "Ann")), CloseCode::bad_request);
  EXPECT_EQ(server.core().abuse().count(Abuse::bad_hello), 1u);
  auto chatter = server.join("r", "Ann");
  ASSERT_TRUE(chatter->welcome);
  for (int i = 0; i < 20; ++i) chatter->send(codec::Chat{0, "spam"});
  EXPECT_EQ(closed_with(*chatter), CloseCode::rate_limited);
  EXPECT_EQ(server.core().abuse().count(Abuse::chat_rate), 1u);
  server.core().state().draining = true;
  auto late = server.join("r", "Bob");
  ASSERT_TRUE(late->closing);
  EXPECT_EQ(server.core().abuse().count(Abuse::shutting_down), 1u);
}

TEST(ClientSession, WithoutAPackageTheNameChoosesAProceduralFace) {
  InMemoryServer server;
  auto first = server.join("a", "Zoe");
  auto again = server.join("b", "Zoe");
  ASSERT_TRUE(first->welcome && again->welcome);
  const std::string asset = first->welcome->avatars.back().asset;
  EXPECT_EQ(again->welcome->avatars.back().asset, asset);
  bool demo = false;
  for (const StoredAvatar& face : server.core().demo_avatars()) demo = demo || face.asset == asset;
  EXPECT_TRUE(demo);
}

TEST(ClientSession, AnUploadedPackageIsTheFaceItNames) {
  InMemoryServer server(InMemoryServer::test_config(2));
  const StoredAvatar& uploaded = server.core().demo_avatars().at(1);
  auto peer = server.join("r", "Ann", {.avatar = uploaded.asset});
  ASSERT_TRUE(peer->welcome);
  EXPECT_EQ(peer->welcome->avatars.back().asset, uploaded.asset);
  EXPECT_EQ(peer->welcome->avatars.back().full_bytes, uploaded.full->size());
}

TEST(ClientSession, WhileDrainingNobodyJoins) {
  InMemoryServer server;
  server.core().state().draining = true;
  auto peer = server.join("r", "Ann");
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->code, CloseCode::shutting_down);
}

// --- join tokens (--auth-secret) ---------------------------------------------

class ClientSessionTokens : public ::testing::Test {
 protected:
  ClientSessionTokens() : server_(config_with([](ServerConfig& c) { c.auth_secret = "s3cret"; })) {}
  std::string token(const std::string& room, const std::string& name, std::int64_t expires_in_s,
                    const std::string& secret = "s3cret") {
    return mint_join_token({room, name, unix_now() + expires_in_s}, secret);
  }
  /// The reason a hello with `token` was refused, or "" if it was welcomed.
  std::string refusal(const std::string& room, const std::string& name, const std::string& with) {
    auto peer = server_.join(room, name, {.token = with});
    if (peer->welcome) return "";
    EXPECT_TRUE(peer->closing);
    if (!peer->closing) return "no answer";
    EXPECT_EQ(peer->closing->code, CloseCode::unauthorized) << peer->closing->reason;
    return peer->closing->reason;
  }
  InMemoryServer server_;
};

TEST_F(ClientSessionTokens, AValidTokenAdmits) {
  EXPECT_EQ(refusal("a", "Ann", token("a", "Ann", 60)), "");
  EXPECT_NE(refusal("a", "Bob", token("a", "", 60)).find("names nobody"), std::string::npos)
      << "a token without a name would admit anyone who saw it";
}

TEST_F(ClientSessionTokens, AnExpiredTokenIsRefused) {
  EXPECT_NE(refusal("a", "Ann", token("a", "Ann", -10)).find("expired"), std::string::npos);
}

TEST_F(ClientSessionTokens, ATokenForAnotherRoomIsRefused) {
  EXPECT_NE(refusal("b", "Ann", token("a", "Ann", 60)).find("another room"), std::string::npos);
}

TEST_F(ClientSessionTokens, ATokenForAnotherNameIsRefused) {
  EXPECT_NE(refusal("a", "Eve", token("a", "Ann", 60)).find("another name"), std::string::npos);
}

TEST_F(ClientSessionTokens, AMissingTokenIsRefused) {
  EXPECT_NE(refusal("a", "Ann", "").find("needs a join token"), std::string::npos);
}

TEST_F(ClientSessionTokens, ATokenSignedWithAnotherSecretIsRefused) {
  EXPECT_NE(refusal("a", "Ann", token("a", "Ann", 60, "guess")).find("signature"), std::string::npos);
  EXPECT_EQ(server_.core().rooms().list().size(), 0u) << "refused joins create no rooms";
}

// --- limits on what a peer sends ---------------------------------------------

TEST(ClientSessionLimits, AnUpstreamMessageOver8KiBIsTooLarge) {
  InMemoryServer server;
  auto peer = server.join("r", "Big");
  ASSERT_TRUE(peer->welcome);
  std::vector<std::uint8_t> huge(codec::kMaxUpstreamMessageBytes + 1, 'x');
  huge[0] = 0x84;
  peer->send_bytes(huge);
  EXPECT_EQ(closed_with(*peer), CloseCode::message_too_large);
}

TEST(ClientSessionLimits, MoreMessagesThanTheBurstAreAFlood) {
  InMemoryServer server;
  auto peer = server.join("r", "Flood");
  ASSERT_TRUE(peer->welcome);
  // The hello took one of the burst's 100; a few more than the rest, sent
  // at once, are a flood (the bucket refills by one every 20 ms meanwhile).
  const int pings = static_cast<int>(limits::kMessageBurst) + 10;
  for (int i = 0; i < pings; ++i) peer->send(codec::Ping{static_cast<std::uint32_t>(i), 0});
  EXPECT_EQ(closed_with(*peer), CloseCode::rate_limited);
  EXPECT_NE(peer->closing->reason.find("at most 50 a second"), std::string::npos);
}

TEST(ClientSessionLimits, MessagesWithinTheRateAreServed) {
  InMemoryServer server;
  auto peer = server.join("r", "Steady");
  ASSERT_TRUE(peer->welcome);
  // 120 pings over 1.2 s: more than the burst, fewer than the burst and
  // what 50 a second add meanwhile.
  for (int i = 0; i < 120; ++i) {
    peer->send(codec::Ping{static_cast<std::uint32_t>(i), 0});
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_TRUE(peer->read_until([&] { return peer->pongs.size() == 120; }));
  EXPECT_FALSE(peer->closing);
}

TEST(ClientSessionLimits, MoreBytesThanTheByteBurstAreAFlood) {
  InMemoryServer server;
  auto peer = server.join("r", "Heavy");
  ASSERT_TRUE(peer->welcome);
  // FACS sentences of 4000 bytes: valid messages (the room refuses the
  // sentence, not the connection), a few past 64 KiB, far under 100 messages.
  codec::Command command;
  command.kind = codec::Command::Kind::facs;
  command.sentence = std::string(4000, 'x');
  const int messages = static_cast<int>(limits::kUpstreamByteBurst / 4000) + 3;
  for (int i = 0; i < messages; ++i) peer->send(command);
  EXPECT_EQ(closed_with(*peer), CloseCode::rate_limited);
  EXPECT_NE(peer->closing->reason.find("64 KiB a second"), std::string::npos);
}

TEST(ClientSessionLimits, MoreChatLinesThanTheChatBurstAreAFlood) {
  InMemoryServer server;
  auto peer = server.join("r", "Chatty");
  ASSERT_TRUE(peer->welcome);
  for (int i = 0; i <= static_cast<int>(limits::kChatBurst); ++i) peer->send(codec::Chat{0, "line " + std::to_string(i)});
  EXPECT_EQ(closed_with(*peer), CloseCode::rate_limited);
  EXPECT_NE(peer->closing->reason.find("chat lines"), std::string::npos);
  EXPECT_TRUE(eventually([&] { return server.core().metrics().chat_lines.load() == limits::kChatBurst; }))
      << "the burst itself is relayed";
}

codec::Command script_command(std::uint32_t request_id) {
  codec::Command command;
  command.request_id = request_id;
  command.kind = codec::Command::Kind::facs;
  command.sentence = "KeepAllFrame BeginKeyFrame 12 1.0 Animate 3 \"Texture\" end";
  return command;
}

/// The answers `peer` got to the commands it sent, by request id.
std::map<std::uint32_t, std::string> results_of(test::InMemoryPeer& peer, std::size_t count) {
  EXPECT_TRUE(peer.read_until([&] { return peer.results.size() >= count; }));
  std::map<std::uint32_t, std::string> errors;
  for (const auto& result : peer.results) errors[result.request_id] = result.error;
  return errors;
}

TEST(ClientSessionLimits, ScriptsPastTheConnectionsBurstAreRefusedWithTheRateAndTheConnectionStays) {
  InMemoryServer server;
  auto peer = server.join("r", "Scripter");
  ASSERT_TRUE(peer->welcome);
  const auto burst = static_cast<std::uint32_t>(limits::kScriptBurst);
  for (std::uint32_t i = 1; i <= burst + 1; ++i) peer->send(script_command(i));
  const auto errors = results_of(*peer, burst + 1);
  for (std::uint32_t i = 1; i <= burst; ++i) EXPECT_EQ(errors.at(i), "") << "script " << i << " of the burst";
  EXPECT_EQ(errors.at(burst + 1).rfind("too many scripts; at most 1 a second: try again in 1 s", 0), 0u)
      << errors.at(burst + 1);
  EXPECT_EQ(server.core().abuse().count(Abuse::script_rate), 1u);
  peer->read_for(1100ms);
  peer->send(script_command(100));
  EXPECT_EQ(results_of(*peer, burst + 2).at(100), "") << "a second later one more is played";
  EXPECT_FALSE(peer->closing);
}

TEST(ClientSessionLimits, AScriptOverTheSentencesBytesIsAMalformedCommand) {
  InMemoryServer server;
  auto peer = server.join("r", "Verbose");
  ASSERT_TRUE(peer->welcome);
  // Laid out by hand (the codec's writer asserts the limit): a FACS command
  // whose sentence is one byte over its 4096.
  std::vector<std::uint8_t> head;
  codec::write_message(script_command(1), head);
  std::vector<std::uint8_t> bytes(head.begin(), head.begin() + 3);  // type, request id 1, kind
  codec::ByteWriter w(bytes);
  const std::string sentence(codec::kMaxSentenceBytes + 1, ' ');
  w.varint(static_cast<std::uint32_t>(sentence.size()));
  w.bytes(std::span(reinterpret_cast<const std::uint8_t*>(sentence.data()), sentence.size()));
  peer->send_bytes(std::move(bytes));
  EXPECT_EQ(closed_with(*peer), CloseCode::protocol_error);
  EXPECT_NE(peer->closing->reason.find("malformed command"), std::string::npos) << peer->closing->reason;
}

TEST(ClientSessionLimits, ScriptsPastTheAddresssRateAreRefusedOnAnyOfItsConnections) {
  InMemoryServer server(config_with([](ServerConfig& c) { c.abuse.scripts = {1.0 / 60, 4}; }));
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");  // the same address
  ASSERT_TRUE(ann->welcome && bob->welcome);
  for (std::uint32_t i = 1; i <= 3; ++i) ann->send(script_command(i));
  ASSERT_EQ(results_of(*ann, 3), (std::map<std::uint32_t, std::string>{{1, ""}, {2, ""}, {3, ""}}));
  bob->send(script_command(4));
  bob->send(script_command(5));
  const auto errors = results_of(*bob, 2);
  EXPECT_EQ(errors.at(4), "") << "the address's fourth";
  EXPECT_EQ(errors.at(5).rfind("too many scripts from your address; try again in ", 0), 0u) << errors.at(5);
  EXPECT_EQ(server.core().abuse().count(Abuse::script_rate), 1u);
  EXPECT_FALSE(bob->closing);
}

TEST(ClientSessionLimits, OnlyAFewMessagesMayWaitForTheWelcome) {
  InMemoryServer server;
  // The room's worker is held, so the hello waits for its welcome while the
  // peer goes on sending.
  std::promise<void> release;
  boost::asio::post(server.core().workers(), [held = release.get_future().share()] { held.wait(); });
  auto peer = server.connect();
  peer->hello("r", "Eager");
  for (std::size_t i = 0; i <= limits::kMaxEarlyMessages; ++i) peer->send(codec::Ping{static_cast<std::uint32_t>(i), 0});
  const bool closed = peer->read_until_closed();
  release.set_value();
  ASSERT_TRUE(closed);
  peer->read();
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->code, CloseCode::rate_limited);
  EXPECT_NE(peer->closing->reason.find("before the welcome"), std::string::npos);
}

TEST(ClientSessionLimits, MessagesSentBeforeTheWelcomeAreHandledAfterIt) {
  InMemoryServer server;
  auto peer = server.connect();
  peer->hello("r", "Eager");
  for (std::uint32_t i = 0; i < limits::kMaxEarlyMessages; ++i) peer->send(codec::Ping{i, 0});
  EXPECT_TRUE(peer->read_until([&] { return peer->pongs.size() == limits::kMaxEarlyMessages; }));
  EXPECT_TRUE(peer->welcome);
}

// --- time-outs ---------------------------------------------------------------

TEST(ClientSessionTimeouts, NoHelloInTimeClosesTheConnection) {
  InMemoryServer server(config_with([](ServerConfig& c) { c.timeouts.handshake = 200ms; }));
  auto peer = server.connect();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(closed_with(*peer), CloseCode::handshake_timeout);
  EXPECT_GE(std::chrono::steady_clock::now() - start, 200ms);
  EXPECT_NE(peer->closing->reason.find("no hello within 0.2 s"), std::string::npos) << peer->closing->reason;
  EXPECT_EQ(server.core().metrics().rejected_joins.load(), 1u);
}

TEST(ClientSessionTimeouts, APeerThatSaysNothingIsClosedWhenIdle) {
  InMemoryServer server(config_with([](ServerConfig& c) { c.timeouts.idle = 300ms; }));
  auto silent = server.join("r", "Silent");
  ASSERT_TRUE(silent->welcome);
  EXPECT_EQ(closed_with(*silent), CloseCode::idle_timeout);
  EXPECT_NE(silent->closing->reason.find("send a ping"), std::string::npos);
}

TEST(ClientSessionTimeouts, PingsKeepAConnectionAlive) {
  InMemoryServer server(config_with([](ServerConfig& c) { c.timeouts.idle = 300ms; }));
  auto pinging = server.join("r", "Pinging");
  ASSERT_TRUE(pinging->welcome);
  for (int i = 0; i < 8; ++i) {
    pinging->send(codec::Ping{static_cast<std::uint32_t>(i), 0});
    pinging->read_for(100ms);
  }
  EXPECT_FALSE(pinging->session().gone()) << (pinging->closing ? pinging->closing->reason : "");
}

TEST(ClientSessionTimeouts, AClosingMessageThePeerDoesNotTakeEndsTheConnectionAnyway) {
  InMemoryServer server(config_with([](ServerConfig& c) { c.timeouts.close = 200ms; }));
  auto peer = server.join("r", "Deaf");
  ASSERT_TRUE(peer->welcome);
  peer->session().set_reading(false);
  peer->session().close(CloseCode::normal, "bye");
  EXPECT_TRUE(eventually([&] { return peer->session().gone(); }, 2s));
  EXPECT_TRUE(peer->session().aborted());
  EXPECT_EQ(peer->session().shut_down(), CloseCode::normal);
}

// --- the send queue ----------------------------------------------------------

TEST(ClientSessionQueue, APeerThatReadsNothingWhileMuchIsSentIsCutOff) {
  InMemoryServer server;
  auto peer = server.join("r", "Deaf");
  ASSERT_TRUE(peer->welcome);
  peer->session().set_reading(false);
  // What a room sends outside the stream (chat, presence) is not skipped;
  // past kMaxQueuedBytes the connection is closed instead of growing.
  const auto chunk = share(std::vector<std::uint8_t>(16 * 1024, 0x84));
  for (std::size_t sent = 0; sent <= limits::kMaxQueuedBytes + chunk->size(); sent += chunk->size())
    peer->session().deliver(chunk);
  EXPECT_TRUE(eventually([&] { return peer->session().gone(); }));
  EXPECT_TRUE(peer->session().aborted());
  EXPECT_EQ(peer->session().shut_down(), CloseCode::rate_limited);
  EXPECT_LE(peer->session().queued_bytes(), limits::kMaxQueuedBytes + chunk->size());
}

TEST(ClientSessionQueue, AfterClosingNothingMoreIsQueued) {
  InMemoryServer server;
  auto peer = server.join("r", "Leaving");
  ASSERT_TRUE(peer->welcome);
  peer->session().close(CloseCode::normal, "bye");
  ASSERT_TRUE(peer->read_until_closed());
  peer->session().deliver(share(std::vector<std::uint8_t>(1000, 0x84)));
  EXPECT_TRUE(eventually([&] { return peer->session().queued_bytes() == 0; }));
  peer->read();
  EXPECT_TRUE(peer->closing);
}

}  // namespace
}  // namespace fw::server
