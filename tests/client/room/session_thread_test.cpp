#include "session_thread.hpp"

#include <chrono>
#include <thread>

#include <boost/asio/error.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "in_memory_transport.hpp"
#include "server_messages.hpp"

namespace fw::client {
namespace {

using namespace std::chrono_literals;
using namespace fw::client::test;

SessionOptions ada() {
  SessionOptions options;
  options.room = "lobby";
  options.name = "ada";
  return options;
}

// Waits (on this thread) until the state says it is in the room.
bool wait_until_joined(RoomState& state, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    {
      std::lock_guard lock(state.mutex);
      if (state.joined) return true;
    }
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

TEST(SessionThread, TheSessionJoinsOnItsOwnThreadAndClosesWhenStopped) {
  RoomState state;
  // The server end lives on the session's io_context; this thread reaches
  // it by posting there, and reads it only after stop() joined the thread.
  boost::asio::io_context* session_io = nullptr;
  std::unique_ptr<InMemoryServerEnd> server;
  SessionThread thread(ada(), state, [&](boost::asio::io_context& io) {
    if (!server) {
      session_io = &io;
      server = std::make_unique<InMemoryServerEnd>(io);
    }
    return server->transports()();
  });
  ASSERT_NE(session_io, nullptr) << "the first connection is opened at once";
  boost::asio::post(*session_io, [&] { server->send(welcome(1, {avatar_info(1, "ada")})); });
  EXPECT_TRUE(wait_until_joined(state, 2s));
  thread.stop();
  EXPECT_TRUE(server->closed_by_client());
  const auto sent = server->take_received();
  ASSERT_FALSE(sent.empty());
  EXPECT_EQ(read_as<codec::Hello>(sent[0]).name, "ada");
  thread.stop();  // again: nothing left to do
}

TEST(SessionThread, StopsPromptlyWhileWaitingToReconnect) {
  RoomState state;
  std::unique_ptr<InMemoryServerEnd> server;
  const auto started = std::chrono::steady_clock::now();
  {
    SessionThread thread(ada(), state, [&](boost::asio::io_context& io) {
      if (!server) {
        server = std::make_unique<InMemoryServerEnd>(io);
        server->refuse_connections(boost::asio::error::connection_refused);
      }
      return server->transports()();
    });
    std::this_thread::sleep_for(100ms);
  }  // destroyed: stopped
  EXPECT_LT(std::chrono::steady_clock::now() - started, 400ms) << "the 500 ms back-off is not waited for";
  EXPECT_EQ(server->attempts(), 1);
  EXPECT_FALSE(wait_until_joined(state, 0ms));
}

}  // namespace
}  // namespace fw::client
