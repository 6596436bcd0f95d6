#include "room_session.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>

#include <boost/asio/error.hpp>
#include <gtest/gtest.h>

#include "in_memory_transport.hpp"
#include "server_messages.hpp"

// The session plays its part of the protocol against a server played by the
// test through an in-memory transport: what comes down is made with the
// codec's writers, what goes up is read with its readers. The io_context
// runs on the test's thread; only the session's own timers (housekeeping
// every 250 ms, reconnection after 500 ms) take real time.
namespace fw::client {
namespace {

using namespace std::chrono_literals;
using namespace fw::client::test;
using Quality = codec::PackageChunk::Quality;

class RoomSessionTest : public ::testing::Test {
 protected:
  static SessionOptions default_options() {
    SessionOptions options;
    options.room = "lobby";
    options.name = "ada";
    return options;
  }

  // Makes the session and starts it; it connects as the io_context runs.
  void launch(SessionOptions options = default_options()) {
    options.on_event = [this](const std::string& text) { events_.push_back(text); };
    session_ = std::make_unique<RoomSession>(io_, std::move(options), state_, server_.transports());
    session_->start();
  }
  void start(SessionOptions options = default_options()) {
    launch(std::move(options));
    ASSERT_TRUE(run_until([&] { return server_.connected(); }));
  }

  // Runs the io_context until `done` holds; false if it did not within `timeout`.
  bool run_until(const std::function<bool()>& done, std::chrono::milliseconds timeout = 2s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      io_.restart();
      if (io_.run_one_for(10ms) == 0 && io_.stopped()) return done();  // nothing left that could change it
    }
    return true;
  }
  // Runs the io_context for `duration` of real time (timers included).
  void run_for(std::chrono::milliseconds duration) {
    io_.restart();
    io_.run_for(duration);
  }
  // Runs every handler that is ready (messages in flight), none that waits for time.
  void settle() {
    io_.restart();
    io_.poll();
  }
  void send(Bytes message) {
    server_.send(std::move(message));
    settle();
  }
  // Starts, reads the hello, and lets the session into a room of `avatars`.
  void join(std::vector<codec::AvatarInfo> avatars = {avatar_info(1, "ada"), avatar_info(2, "bob")},
            SessionOptions options = default_options()) {
    start(std::move(options));
    settle();
    send(welcome(1, std::move(avatars)));
    send(stream_header());
  }

  // What the session sent up so far, taken out, without its pings (which
  // go out on a timer whenever a slow test gives it the time).
  std::vector<Bytes> upstream() {
    settle();
    std::vector<Bytes> sent = server_.take_received();
    std::erase_if(sent, [](const Bytes& m) {
      return codec::classify(m) == codec::MessageKind::session && codec::session_type(m) == codec::MessageType::ping;
    });
    return sent;
  }
  bool joined() {
    std::lock_guard lock(state_.mutex);
    return state_.joined;
  }
  bool saw_event(const std::string& part) const {
    return std::any_of(events_.begin(), events_.end(),
                       [&](const std::string& e) { return e.find(part) != std::string::npos; });
  }

  boost::asio::io_context io_;
  InMemoryServerEnd server_{io_};
  RoomState state_;
  std::vector<std::string> events_;
  std::unique_ptr<RoomSession> session_;
};

codec::MessageType type_of(const Bytes& message) { return codec::session_type(message); }

// --- Joining ---------------------------------------------------------------

TEST_F(RoomSessionTest, SaysHelloFirstWithWhatItWasAskedFor) {
  SessionOptions options = default_options();
  options.avatar_asset = "asset1";
  options.token = "fw1.token";
  options.max_bps = 9600;
  options.timestamps = false;
  options.own_package = std::make_shared<const Bytes>(Bytes{1, 2, 3});
  start(options);
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  const auto hello = read_as<codec::Hello>(sent[0]);
  EXPECT_EQ(hello.room, "lobby");
  EXPECT_EQ(hello.name, "ada");
  EXPECT_EQ(hello.avatar, "asset1");
  EXPECT_EQ(hello.token, "fw1.token");
  EXPECT_EQ(hello.max_bps, 9600u);
  EXPECT_FALSE(hello.timestamps);
  EXPECT_TRUE(hello.own_package) << "an uploaded package is not sent back";
  EXPECT_EQ(hello.protocol_version, 5);
  EXPECT_EQ(hello.language, "") << "the server's default language";
  EXPECT_FALSE(joined()) << "not in the room before the welcome";
}

TEST_F(RoomSessionTest, ItsLanguageGoesInTheHelloAndARefusalOfItIsPrintedAsItComes) {
  SessionOptions options = default_options();
  options.language = "pt-br";
  start(options);
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(read_as<codec::Hello>(sent[0]).language, "pt-br");
  send(closing(codec::CloseCode::bad_request,
               "unknown language 'pt-br'; GET /api/languages lists the ones this server speaks"));
  EXPECT_TRUE(saw_event("server: unknown language 'pt-br'; GET /api/languages lists the ones this server speaks"));
  std::lock_guard lock(state_.mutex);
  ASSERT_TRUE(state_.fatal_error);
  EXPECT_NE(state_.fatal_error->find("(closing code 10)"), std::string::npos) << *state_.fatal_error;
}

TEST_F(RoomSessionTest, TheWelcomeLetsItIntoTheRoomWithEveryoneInIt) {
  join({avatar_info(1, "ada"), avatar_info(2, "bob"), avatar_info(5, "cyd")});
  std::lock_guard lock(state_.mutex);
  EXPECT_TRUE(state_.joined);
  EXPECT_EQ(state_.you, 1u);
  EXPECT_EQ(state_.room, "lobby");
  ASSERT_EQ(state_.avatars.size(), 3u);
  EXPECT_EQ(state_.avatars.at(5).info.name, "cyd");
  EXPECT_TRUE(saw_event("joined room lobby as avatar 1 with 3 avatar(s) present"));
}

TEST_F(RoomSessionTest, ItsOwnUploadedPackageIsItsFaceAtOnce) {
  SessionOptions options = default_options();
  options.own_package = std::make_shared<const Bytes>(Bytes{7, 7, 7});
  join({avatar_info(1, "ada", "mine")}, options);
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.avatars.at(1).package, options.own_package);
  EXPECT_EQ(state_.avatars.at(1).package_quality, Quality::full);
}

TEST_F(RoomSessionTest, SaysItsLinesAndShowsItsEmotionOnceJoined) {
  SessionOptions options = default_options();
  options.say = {"hello", "anyone here?"};
  options.emote = "joy";
  start(options);
  EXPECT_EQ(upstream().size(), 1u) << "nothing but the hello before the welcome";
  send(welcome(1, {avatar_info(1, "ada")}));
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 3u);
  EXPECT_EQ(read_as<codec::Chat>(sent[0]).text, "hello");
  EXPECT_EQ(read_as<codec::Chat>(sent[1]).text, "anyone here?");
  const auto command = read_as<codec::Command>(sent[2]);
  EXPECT_EQ(command.kind, codec::Command::Kind::express);
  EXPECT_EQ(command.emotion, "joy");
  EXPECT_EQ(command.duration_ms, 3000u);
}

TEST_F(RoomSessionTest, ChatLinesGoUp) {
  join();
  upstream();
  session_->chat("hi all");
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(read_as<codec::Chat>(sent[0]).text, "hi all");
}

TEST_F(RoomSessionTest, ALookLinePlaysASavedLookInsteadOfSayingIt) {
  join();
  upstream();
  session_->chat("/look blush slowly");
  auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  const auto command = read_as<codec::Command>(sent[0]);
  EXPECT_EQ(command.kind, codec::Command::Kind::play_look);
  EXPECT_EQ(command.sentence, "blush slowly");
  session_->chat("/look " + std::string(codec::kMaxLookNameBytes + 1, 'x'));
  EXPECT_TRUE(upstream().empty()) << "a name no server takes was sent";
  EXPECT_TRUE(saw_event("/look takes the name"));
  session_->chat("/looking good");
  sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(read_as<codec::Chat>(sent[0]).text, "/looking good");
}

TEST_F(RoomSessionTest, ANewBudgetIsAskedForAndKeptForTheNextConnection) {
  join();
  upstream();
  session_->set_rate(4800);
  auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(read_as<codec::SetRate>(sent[0]).max_bps, 4800u);
  server_.drop();
  ASSERT_TRUE(run_until([&] { return server_.attempts() == 2 && server_.connected(); }));
  sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(read_as<codec::Hello>(sent[0]).max_bps, 4800u);
}

TEST_F(RoomSessionTest, AFullUpstreamQueueDropsMessagesAndSaysSo) {
  join();
  upstream();
  // Nothing runs between these calls, so no write completes: the queue fills.
  for (std::size_t i = 0; i < RoomSession::kMaxOutbox + 5; ++i) session_->chat("line " + std::to_string(i));
  // (A ping due while the queue is full is dropped too.)
  EXPECT_GE(std::count(events_.begin(), events_.end(), "upstream queue full: a message was dropped"), 5);
  EXPECT_EQ(upstream().size(), RoomSession::kMaxOutbox);
}

// --- The room's faces ------------------------------------------------------

TEST_F(RoomSessionTest, DecodesRoomFramesIntoEveryAvatarsFace) {
  join();
  FaceStream ada, bob;
  send(room_frame({{1, ada.frame(face(0.2f))}, {2, bob.frame(face(0.9f))}}));
  std::lock_guard lock(state_.mutex);
  const auto faces = state_.faces(state_.avatars.at(2).last_frame_at);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].avatar, 1u);
  EXPECT_EQ(codec::quantise(faces[0].params), ada.reconstruction());
  EXPECT_EQ(faces[1].avatar, 2u);
  EXPECT_EQ(codec::quantise(faces[1].params), bob.reconstruction());
  EXPECT_EQ(state_.stats.frames_of(2), 1u);
  EXPECT_EQ(state_.stats.avatars_seen(), 2u);
}

TEST_F(RoomSessionTest, FramesFasterThanTheRendererLeaveOnlyTheNewestFace) {
  join();
  FaceStream bob;
  // Three frames arrive before the renderer looks: each is decoded (the
  // predicted ones build on the last), only the newest is drawn.
  send(room_frame({{2, bob.frame(face(0.1f))}}));
  const codec::QuantisedParams first = bob.reconstruction();
  send(room_frame({{2, bob.frame(face(0.5f))}}));
  send(room_frame({{2, bob.frame(face(1.0f))}}));
  std::lock_guard lock(state_.mutex);
  const auto faces = state_.faces(state_.avatars.at(2).last_frame_at);
  ASSERT_EQ(faces.size(), 1u) << "ada sent no frame yet, so she is not drawn";
  EXPECT_EQ(codec::quantise(faces[0].params), bob.reconstruction());
  EXPECT_NE(codec::quantise(faces[0].params), first);
  EXPECT_EQ(state_.stats.frames_of(2), 3u);
}

TEST_F(RoomSessionTest, AsksForAKeyFrameWhenADecoderNeedsOne) {
  join();
  FaceStream bob;
  bob.frame(face(0.2f));  // the key frame, lost on its way
  send(room_frame({{2, bob.frame(face(0.8f))}}));
  std::vector<std::uint32_t> asked;
  ASSERT_TRUE(run_until([&] {
    for (const Bytes& message : server_.take_received()) {
      if (codec::classify(message) == codec::MessageKind::resync_request) {
        EXPECT_EQ(codec::read_resync_request(message, asked), codec::DecodeError::ok);
      }
    }
    return !asked.empty();
  }));
  EXPECT_EQ(asked, (std::vector<std::uint32_t>{2}));
  std::lock_guard lock(state_.mutex);
  EXPECT_TRUE(state_.faces(std::chrono::steady_clock::now()).empty()) << "no face before its key frame";
}

TEST_F(RoomSessionTest, PingsInTheRoomAndMeasuresLatencyFromTimedFrames) {
  join();
  std::optional<codec::Ping> ping;
  ASSERT_TRUE(run_until([&] {
    for (const Bytes& message : server_.take_received())
      if (type_of(message) == codec::MessageType::ping) ping = read_as<codec::Ping>(message);
    return ping.has_value();
  }));
  // A server whose clock runs 5 s ahead answers at once.
  constexpr std::uint64_t kAhead = 5'000'000;
  send(bytes_of(codec::Pong{ping->nonce, ping->client_time_us, ping->client_time_us + kAhead}));
  FaceStream bob;
  const std::uint64_t now_server = ping->client_time_us + kAhead;
  send(timed(room_frame({{2, bob.frame(face(0.4f))}}), 1, now_server));
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.stats.frames_of(2), 1u);
  EXPECT_GE(state_.stats.latency_percentile_ms(50), 0.0) << "a latency was measured";
  EXPECT_LT(state_.stats.latency_percentile_ms(50), 2000.0);
}

TEST_F(RoomSessionTest, NoPingBeforeTheWelcome) {
  start();
  run_for(RoomSession::kHousekeepingInterval * 2);
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(type_of(sent[0]), codec::MessageType::hello);
}

// --- Packages, presence, chat and the server's other messages ---------------

TEST_F(RoomSessionTest, AssemblesPackagesPreviewFirstThenFull) {
  join();
  const Bytes preview(100, 1), full(5000, 2);
  for (Bytes chunk : package_chunks(2, Quality::preview, preview, 64)) send(std::move(chunk));
  {
    std::lock_guard lock(state_.mutex);
    ASSERT_TRUE(state_.avatars.at(2).package);
    EXPECT_EQ(*state_.avatars.at(2).package, preview);
    EXPECT_EQ(state_.avatars.at(2).package_quality, Quality::preview);
  }
  for (Bytes chunk : package_chunks(2, Quality::full, full, 1024)) send(std::move(chunk));
  for (Bytes chunk : package_chunks(2, Quality::preview, preview, 64)) send(std::move(chunk));
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(*state_.avatars.at(2).package, full) << "a late preview never replaces the full package";
  EXPECT_EQ(state_.avatars.at(2).package_serial, 2u);
}

TEST_F(RoomSessionTest, ABrokenPackageIsReportedAndDropped) {
  join();
  const auto chunks = package_chunks(2, Quality::full, Bytes(300, 3), 100);
  send(chunks[0]);
  send(chunks[2]);  // the middle one went missing
  EXPECT_TRUE(saw_event("out of order"));
  std::lock_guard lock(state_.mutex);
  EXPECT_FALSE(state_.avatars.at(2).package);
}

TEST_F(RoomSessionTest, ArrivalsAndDeparturesChangeTheRoom) {
  join();
  FaceStream bob;
  send(room_frame({{2, bob.frame(face(0.3f))}}));
  send(presence(codec::Presence::Change::joined, avatar_info(9, "eve")));
  send(presence(codec::Presence::Change::left, avatar_info(2, "")));
  EXPECT_TRUE(saw_event("eve joined"));
  EXPECT_TRUE(saw_event("bob left"));
  std::lock_guard lock(state_.mutex);
  EXPECT_TRUE(state_.avatars.contains(9));
  EXPECT_FALSE(state_.avatars.contains(2));
  EXPECT_EQ(state_.decoder.avatar(2), nullptr) << "a departed avatar's decoder goes";
  ASSERT_EQ(state_.events.size(), 2u);
  EXPECT_EQ(state_.events[1].kind, "left");
  EXPECT_EQ(state_.events[1].name, "bob");
}

TEST_F(RoomSessionTest, ChatRefusedCommandsAndLinkStatisticsReachThePerson) {
  join();
  send(chat_from(2, "hi ada"));
  send(bytes_of(codec::CommandResult{1, "unknown emotion"}));
  send(bytes_of(codec::LinkStats{9600, 9000, 120, 3}));
  EXPECT_TRUE(saw_event("bob: hi ada"));
  EXPECT_TRUE(saw_event("command refused: unknown emotion"));
  std::lock_guard lock(state_.mutex);
  ASSERT_EQ(state_.events.size(), 1u);
  EXPECT_EQ(state_.events[0].text, "hi ada");
  ASSERT_TRUE(state_.server_link);
  EXPECT_EQ(state_.server_link->skipped_ticks, 3u);
}

TEST_F(RoomSessionTest, ALineBegunIsShownWithItsLanguageAndLength) {
  join();
  send(bytes_of(codec::Speaking{2, 90, 1840, "fr", "bonjour à tous"}));
  send(chat_from(2, "bonjour à tous"));
  EXPECT_TRUE(saw_event("bob: bonjour à tous")) << "the session goes on after a speaking message";
  std::lock_guard lock(state_.mutex);
  ASSERT_EQ(state_.events.size(), 2u);
  EXPECT_EQ(state_.events[0].kind, "speaking");
  EXPECT_EQ(state_.events[0].language, "fr");
  EXPECT_EQ(state_.events[0].duration_ms, 1840u);
  EXPECT_TRUE(saw_event("bob says (fr, 1840 ms): bonjour à tous"));
}

TEST_F(RoomSessionTest, CountsTheBytesOfBothDirections) {
  start();
  const Bytes hello = upstream().at(0);
  {
    std::lock_guard lock(state_.mutex);
    EXPECT_EQ(state_.stats.total_bytes_up(), hello.size()) << "nothing is added to a message in memory";
  }
  const Bytes message = welcome(1, {avatar_info(1, "ada")});
  send(message);
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.stats.total_bytes_down(), message.size());
}

// --- Drops, closes and errors ---------------------------------------------

TEST_F(RoomSessionTest, ReconnectsAfterADropAndSaysHelloAgainButNotItsLines) {
  SessionOptions options = default_options();
  options.say = {"once"};
  join({avatar_info(1, "ada")}, options);
  upstream();
  server_.drop();
  settle();
  EXPECT_FALSE(joined());
  EXPECT_TRUE(saw_event("the server closed the connection; reconnecting in 500 ms"));
  ASSERT_TRUE(run_until([&] { return server_.attempts() == 2 && server_.connected(); }));
  const auto sent = upstream();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(type_of(sent[0]), codec::MessageType::hello);
  send(welcome(1, {avatar_info(1, "ada")}));
  EXPECT_TRUE(joined());
  EXPECT_TRUE(upstream().empty()) << "--say lines go out after the first welcome only";
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.stats.summary(std::chrono::steady_clock::now())["reconnects"], 1);
}

TEST_F(RoomSessionTest, KeepsTryingWhileTheServerIsDown) {
  server_.refuse_connections(boost::asio::error::connection_refused);
  launch();
  EXPECT_EQ(server_.attempts(), 1);
  ASSERT_TRUE(run_until([&] { return server_.attempts() == 2; }));
  EXPECT_TRUE(saw_event("cannot connect: "));
  server_.refuse_connections({});
  ASSERT_TRUE(run_until([&] { return server_.connected(); }, 3s)) << "the second wait is a second long";
  EXPECT_EQ(server_.attempts(), 3);
}

TEST_F(RoomSessionTest, ARefusalThatRetryingCannotFixEndsTheSession) {
  start();
  send(closing(codec::CloseCode::unauthorized, "the token has expired"));
  EXPECT_TRUE(server_.closed_by_client());
  EXPECT_TRUE(saw_event("server: the token has expired"));
  {
    std::lock_guard lock(state_.mutex);
    ASSERT_TRUE(state_.fatal_error);
    EXPECT_NE(state_.fatal_error->find("the token has expired (closing code 4)"), std::string::npos);
  }
  run_for(RoomSession::backoff(1) + 200ms);
  EXPECT_EQ(server_.attempts(), 1) << "no reconnection";
}

TEST_F(RoomSessionTest, AServerThatShutsDownIsTriedAgain) {
  join();
  send(closing(codec::CloseCode::shutting_down, "restarting"));
  EXPECT_TRUE(saw_event("the server closed the connection: restarting; reconnecting in 500 ms"));
  std::lock_guard lock(state_.mutex);
  EXPECT_FALSE(state_.fatal_error);
  EXPECT_FALSE(state_.joined);
}

TEST_F(RoomSessionTest, MessagesAClientDoesNotExpectDropTheConnection) {
  join();
  send(Bytes{0x00, 0x01});
  EXPECT_TRUE(saw_event("a message a client does not expect (first byte 0)"));
  EXPECT_TRUE(server_.closed_by_client());
  ASSERT_TRUE(run_until([&] { return server_.connected(); }));
  codec::Hello hello;
  hello.room = "lobby";
  hello.name = "ada";
  send(bytes_of(hello));  // an upstream message coming down
  EXPECT_TRUE(saw_event("malformed message from the server (type 1)"));
  EXPECT_EQ(server_.attempts(), 2);
}

TEST_F(RoomSessionTest, ABadRoomFrameIsCountedNotFatal) {
  join();
  send(Bytes{0x23, 0xff, 0xff});
  EXPECT_TRUE(server_.connected());
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.stats.summary(std::chrono::steady_clock::now())["decode_errors"], 1);
}

TEST_F(RoomSessionTest, StopClosesTheConnectionForGood) {
  join();
  session_->stop();
  settle();
  EXPECT_TRUE(server_.closed_by_client());
  run_for(RoomSession::backoff(1) + 200ms);
  EXPECT_EQ(server_.attempts(), 1);
}

TEST(RoomSessionBackoff, DoublesFromHalfASecondToEight) {
  const std::vector<long> expected = {500, 500, 1000, 2000, 4000, 8000, 8000};
  for (int attempts = 0; attempts < 7; ++attempts)
    EXPECT_EQ(RoomSession::backoff(attempts).count(), expected[static_cast<std::size_t>(attempts)]) << attempts;
}

}  // namespace
}  // namespace fw::client
