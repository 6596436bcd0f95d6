#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>

#include <boost/asio/error.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "in_memory_transport.hpp"
#include "room_session.hpp"
#include "server_messages.hpp"

// The session given several servers (SessionOptions::servers): it moves on
// to the next when a link fails, keeps its name, token and resume key, and
// uploads its face to a server that does not know it. Each server is an
// in-memory end that the test drives; only the back-off takes real time.
namespace fw::client {
namespace {

using namespace std::chrono_literals;
using namespace fw::client::test;

class FailoverTest : public ::testing::Test {
 protected:
  static SessionOptions two_servers() {
    SessionOptions options;
    options.room = "lobby";
    options.name = "ada";
    options.token = "fw1.ada";
    options.servers = {"ws://a:8080/", "ws://b:8080/"};
    return options;
  }
  // Options of a person who uploaded a face to the first server.
  static SessionOptions with_face() {
    SessionOptions options = two_servers();
    options.avatar_asset = "asset-a";
    options.avatar_key = "key-a";
    return options;
  }

  void start(SessionOptions options) {
    options.on_event = [this](const std::string& text) { events_.push_back(text); };
    if (with_reupload_)
      options.reupload = [this](std::size_t server, ReuploadDone done) {
        uploads_.push_back(server);
        // Answered later, on the io_context, as a real upload would be.
        boost::asio::post(io_, [this, done = std::move(done)] { done(upload_result_); });
      };
    session_ = std::make_unique<RoomSession>(io_, std::move(options), state_, [this](std::size_t server) {
      return ends_.at(server)->transports()();
    });
    session_->start();
  }

  bool run_until(const std::function<bool()>& done, std::chrono::milliseconds timeout = 3s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      io_.restart();
      io_.run_one_for(10ms);
    }
    return true;
  }
  void settle() {
    io_.restart();
    io_.poll();
  }
  InMemoryServerEnd& server(std::size_t index) { return *ends_.at(index); }
  void send(std::size_t index, Bytes message) {
    server(index).send(std::move(message));
    settle();
  }
  // The hellos server `index` received since the last look.
  std::vector<codec::Hello> hellos(std::size_t index) {
    settle();
    std::vector<codec::Hello> found;
    for (const Bytes& m : server(index).take_received())
      if (codec::classify(m) == codec::MessageKind::session && codec::session_type(m) == codec::MessageType::hello)
        found.push_back(read_as<codec::Hello>(m));
    return found;
  }
  // Connects to server `index` (it must be the next) and reads its hello.
  codec::Hello hello_at(std::size_t index) {
    EXPECT_TRUE(run_until([&] { return server(index).connected(); })) << "no connection to server " << index;
    auto found = hellos(index);
    EXPECT_EQ(found.size(), 1u);
    return found.empty() ? codec::Hello{} : found.front();
  }
  Bytes welcome_with_resume(const std::string& resume) {
    codec::Welcome message;
    message.you = 1;
    message.room = "lobby";
    message.avatars = {avatar_info(1, "ada")};
    message.resume = resume;
    return bytes_of(message);
  }
  bool joined() {
    std::lock_guard lock(state_.mutex);
    return state_.joined;
  }
  std::optional<std::string> fatal() {
    std::lock_guard lock(state_.mutex);
    return state_.fatal_error;
  }
  bool saw_event(const std::string& part) const {
    return std::any_of(events_.begin(), events_.end(), [&](const std::string& e) { return e.find(part) != std::string::npos; });
  }

  boost::asio::io_context io_;
  std::vector<std::unique_ptr<InMemoryServerEnd>> ends_ = [this] {
    std::vector<std::unique_ptr<InMemoryServerEnd>> ends;
    for (int i = 0; i < 3; ++i) ends.push_back(std::make_unique<InMemoryServerEnd>(io_));
    return ends;
  }();
  RoomState state_;
  std::vector<std::string> events_;
  bool with_reupload_ = true;
  ReuploadResult upload_result_{.ok = true, .credentials = {"asset-b", "key-b"}, .try_elsewhere = false, .error = ""};
  std::vector<std::size_t> uploads_;
  std::unique_ptr<RoomSession> session_;
};

TEST_F(FailoverTest, ADroppedServerGivesWayToTheNextWithTheSameNameTokenAndResumeKey) {
  start(two_servers());
  EXPECT_EQ(hello_at(0).name, "ada");
  send(0, welcome_with_resume("resume-1"));
  ASSERT_TRUE(joined());
  EXPECT_TRUE(saw_event("joined room lobby as avatar 1 with 1 avatar(s) present on ws://a:8080/"));
  server(0).drop();
  settle();
  EXPECT_TRUE(saw_event("the server closed the connection; moving to ws://b:8080/ (server 2 of 2) in 500 ms"));
  const codec::Hello hello = hello_at(1);
  EXPECT_EQ(hello.name, "ada");
  EXPECT_EQ(hello.token, "fw1.ada");
  EXPECT_EQ(hello.resume, "resume-1") << "the token passes to the new connection";
  EXPECT_EQ(server(0).attempts(), 1);
  send(1, welcome_with_resume("resume-2"));
  EXPECT_TRUE(joined());
  std::lock_guard lock(state_.mutex);
  EXPECT_EQ(state_.server, "ws://b:8080/");
}

TEST_F(FailoverTest, AServerThatCannotBeReachedPassesToTheNextAndTheListGoesRound) {
  server(0).refuse_connections(boost::asio::error::connection_refused);
  start(two_servers());
  EXPECT_EQ(hello_at(1).name, "ada");
  EXPECT_TRUE(saw_event("cannot connect: "));
  EXPECT_TRUE(saw_event("moving to ws://b:8080/ (server 2 of 2)"));
  server(0).refuse_connections({});
  send(1, closing(codec::CloseCode::shutting_down, "the server is shutting down; try again soon"));
  EXPECT_TRUE(saw_event("the server is shutting down; try again soon; moving to ws://a:8080/ (server 1 of 2)"));
  EXPECT_EQ(hello_at(0).name, "ada") << "after the last server, the first";
  EXPECT_FALSE(fatal());
}

TEST_F(FailoverTest, ARefusalNoServerWouldChangeEndsTheSession) {
  with_reupload_ = false;  // no face of its own: nothing an upload could mend
  start(two_servers());
  hello_at(0);
  send(0, closing(codec::CloseCode::unauthorized, "the token has expired"));
  ASSERT_TRUE(fatal());
  EXPECT_NE(fatal()->find("the token has expired (closing code 4)"), std::string::npos);
  io_.restart();
  io_.run_for(RoomSession::backoff(1) + 200ms);
  EXPECT_EQ(server(1).attempts(), 0) << "another server would say the same";
}

TEST_F(FailoverTest, AFaceBeingPreparedIsAskedForAgainWhereItIsPrepared) {
  start(two_servers());
  hello_at(0);
  send(0, closing(codec::CloseCode::avatar_being_prepared, "your avatar is being prepared"));
  EXPECT_TRUE(saw_event("reconnecting in 500 ms"));
  EXPECT_EQ(hello_at(0).name, "ada");
  EXPECT_EQ(server(1).attempts(), 0);
}

TEST_F(FailoverTest, AServerThatDoesNotKnowTheFaceGetsItUploadedOnce) {
  start(with_face());
  const codec::Hello first = hello_at(0);
  EXPECT_EQ(first.avatar, "asset-a");
  send(0, welcome_with_resume("r"));
  server(0).drop();
  settle();
  // The next node may share the first one's avatars: the same face is tried first.
  const codec::Hello second = hello_at(1);
  EXPECT_EQ(second.avatar, "asset-a");
  EXPECT_EQ(second.avatar_key, "key-a");
  send(1, closing(codec::CloseCode::bad_request, "unknown avatar 'asset-a'; upload it first (POST /api/avatars)"));
  EXPECT_TRUE(saw_event("ws://b:8080/ refused the face (unknown avatar 'asset-a'"));
  ASSERT_TRUE(run_until([&] { return server(1).attempts() == 2 && server(1).connected(); }));
  EXPECT_EQ(uploads_, std::vector<std::size_t>{1});
  EXPECT_TRUE(saw_event("uploaded the face to ws://b:8080/"));
  const auto third = hellos(1);
  ASSERT_EQ(third.size(), 1u);
  EXPECT_EQ(third[0].avatar, "asset-b") << "what the upload there answered";
  EXPECT_EQ(third[0].avatar_key, "key-b");
  EXPECT_EQ(third[0].name, "ada");
  // Refused again after the upload: that refusal is for good.
  send(1, closing(codec::CloseCode::bad_request, "that name is taken by nobody, but refused"));
  ASSERT_TRUE(fatal());
  EXPECT_EQ(uploads_.size(), 1u);
}

TEST_F(FailoverTest, EachServerGetsTheFaceItWasGiven) {
  start(with_face());
  hello_at(0);
  server(0).drop();
  settle();
  hello_at(1);
  send(1, closing(codec::CloseCode::unauthorized, "that is not the key of this face"));
  ASSERT_TRUE(run_until([&] { return server(1).attempts() == 2 && server(1).connected(); }));
  EXPECT_EQ(hellos(1).at(0).avatar_key, "key-b");
  send(1, welcome_with_resume("r"));
  server(1).drop();
  settle();
  const codec::Hello back = hello_at(0);
  EXPECT_EQ(back.avatar, "asset-a") << "the first server's own upload";
  EXPECT_EQ(back.avatar_key, "key-a");
}

TEST_F(FailoverTest, TheServerTheFaceWentToFirstRefusesForGood) {
  start(with_face());
  hello_at(0);
  send(0, closing(codec::CloseCode::unauthorized, "that is not the key of this face: only who uploaded it may wear it"));
  EXPECT_TRUE(fatal());
  EXPECT_TRUE(uploads_.empty());
}

TEST_F(FailoverTest, AnUploadThatMayWorkElsewhereMovesOnAndOneRefusedForGoodEndsTheSession) {
  upload_result_ = {.ok = false, .credentials = {}, .try_elsewhere = true, .error = "the server's uploads are at their limit (503)"};
  start(with_face());
  hello_at(0);
  server(0).drop();
  settle();
  hello_at(1);
  send(1, closing(codec::CloseCode::bad_request, "unknown avatar"));
  EXPECT_TRUE(run_until([&] { return saw_event("uploading the face to ws://b:8080/: the server's uploads are at their limit (503); moving to ws://a:8080/"); }));
  EXPECT_EQ(hello_at(0).avatar, "asset-a");
  EXPECT_FALSE(fatal());

  // Back at the server whose upload failed: it is asked again.
  upload_result_ = {.ok = false, .credentials = {}, .try_elsewhere = false, .error = "the server refused the avatar (401): no token"};
  server(0).drop();
  settle();
  hello_at(1);
  send(1, closing(codec::CloseCode::bad_request, "unknown avatar"));
  ASSERT_TRUE(run_until([&] { return fatal().has_value(); }));
  EXPECT_EQ(uploads_, (std::vector<std::size_t>{1, 1}));
  EXPECT_EQ(*fatal(), "uploading the face to ws://b:8080/: the server refused the avatar (401): no token");
}

TEST_F(FailoverTest, OneServerIsRetriedAsBefore) {
  SessionOptions options = two_servers();
  options.servers = {"ws://a:8080/"};
  start(options);
  hello_at(0);
  server(0).drop();
  settle();
  EXPECT_TRUE(saw_event("the server closed the connection; reconnecting in 500 ms"));
  EXPECT_EQ(hello_at(0).name, "ada");
}

}  // namespace
}  // namespace fw::client
