// Redis for cluster mode: URLs without sockets, then RedisConnection on an
// Asio loop against a real redis-server that each test starts on a free
// loopback port (support/redis_process.hpp): binary values of any size,
// pipelining, pub/sub between two connections, Redis killed, restarted and
// stopped (SIGSTOP), a dead port, and connections destroyed mid-flight.
#include "redis_connection.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "redis_process.hpp"
#include "redis_reply.hpp"
#include "redis_url.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// ---- URLs -----------------------------------------------------------------

RedisAddress parsed(const std::string& url) {
  std::string error;
  const auto address = parse_redis_url(url, error);
  EXPECT_TRUE(address) << url << ": " << error;
  return address.value_or(RedisAddress{});
}

TEST(RedisUrl, ReadsHostPortAndDatabase) {
  const auto full = parsed("redis://127.0.0.1:6380/2");
  EXPECT_EQ(full.host, "127.0.0.1");
  EXPECT_EQ(full.port, 6380);
  EXPECT_EQ(full.db, 2);
  EXPECT_TRUE(full.password.empty());

  const auto bare = parsed("redis://redis-0.redis.default.svc");
  EXPECT_EQ(bare.host, "redis-0.redis.default.svc");
  EXPECT_EQ(bare.port, 6379) << "the default port";
  EXPECT_EQ(bare.db, 0) << "the default database";
  EXPECT_EQ(parsed("REDIS://Cache_1:7000/").db, 0) << "the scheme in any case; a lone slash is db 0";

  const auto v6 = parsed("redis://[::1]:7001/15");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 7001);
  EXPECT_EQ(v6.db, 15);
  EXPECT_EQ(parsed("redis://[fe80::1]").port, 6379);

  const auto secret = parsed("redis://:s3cr%40t/x@cache:6379/1");
  EXPECT_EQ(secret.password, "s3cr@t/x") << "percent-decoded; the user part ends at the last '@'";
  EXPECT_TRUE(secret.username.empty());
  EXPECT_EQ(secret.host, "cache");
  EXPECT_EQ(secret.db, 1);
  const auto user = parsed("redis://node:pw@cache");
  EXPECT_EQ(user.username, "node");
  EXPECT_EQ(user.password, "pw");
  const auto user_alone = parsed("redis://node@cache");
  EXPECT_EQ(user_alone.username, "node") << "the password comes from --redis-password-file";
  EXPECT_TRUE(user_alone.password.empty());
}

TEST(RedisUrl, ThePasswordFileGivesItsFirstLine) {
  const std::string path = ::testing::TempDir() + "fw-redis-password-" + std::to_string(::getpid());
  std::string error;
  std::ofstream(path) << "s3cret pass\r\nsecond line\n";
  EXPECT_EQ(read_redis_password_file(path, error).value_or("?"), "s3cret pass") << error;
  std::ofstream(path) << "\n";
  EXPECT_FALSE(read_redis_password_file(path, error));
  EXPECT_NE(error.find("is empty"), std::string::npos) << error;
  std::remove(path.c_str());
  EXPECT_FALSE(read_redis_password_file(path, error));
  EXPECT_NE(error.find("cannot read the Redis password file " + path), std::string::npos) << error;
}

TEST(RedisUrl, PrintsTheAddressWithoutCredentials) {
  EXPECT_EQ(to_string(parsed("redis://cache")), "redis://cache:6379/0");
  EXPECT_EQ(to_string(parsed("redis://[::1]:7001/3")), "redis://[::1]:7001/3");
  EXPECT_EQ(to_string(parsed("redis://:hunter2@10.0.0.5:6380/1")), "redis://10.0.0.5:6380/1");
}

TEST(RedisUrl, RefusesBadFormsSayingWhatWasWrong) {
  const struct {
    const char* url;
    const char* says;
  } cases[] = {
      {"", "must start with redis://"},
      {"127.0.0.1:6379", "must start with redis://"},
      {"http://cache:6379", "must start with redis://"},
      {"rediss://cache:6379", "TLS (rediss://) is not supported"},
      {"unix:///run/redis.sock", "Unix sockets are not supported"},
      {"redis://", "there is no host"},
      {"redis://:6379", "there is no host"},
      {"redis://cache:", "the port must be a number from 1 to 65535, not ''"},
      {"redis://cache:0", "the port must be a number from 1 to 65535, not '0'"},
      {"redis://cache:65536", "the port must be a number from 1 to 65535"},
      {"redis://cache:63x9", "the port must be a number from 1 to 65535, not '63x9'"},
      {"redis://cache:-1", "the port must be a number"},
      {"redis://::1:6379", "an IPv6 address goes in brackets"},
      {"redis://[::1:6379", "has no ']'"},
      {"redis://[cache]:6379", "in brackets is not an IPv6 address"},
      {"redis://[::1]6379", "only ':PORT' may follow"},
      {"redis://cache:6379/one", "the database after '/' must be a number"},
      {"redis://cache:6379/-1", "the database after '/' must be a number"},
      {"redis://cache:6379/1/2", "the database after '/' must be a number"},
      {"redis://cache?db=1", "options after '?' or '#' are not supported"},
      {"redis://ca che", "has characters no host name has"},
      {"redis://@cache", "must be USER, :PASSWORD or USER:PASSWORD"},
      {"redis://:@cache", "the password after ':' is empty"},
      {"redis://:pw%2@cache", "must start a %XX escape"},
  };
  for (const auto& [url, says] : cases) {
    std::string error;
    EXPECT_FALSE(parse_redis_url(url, error)) << url;
    EXPECT_NE(error.find(says), std::string::npos) << url << " -> " << error;
    EXPECT_NE(error.find("expected redis://HOST[:PORT][/DB]"), std::string::npos) << error;
  }
  std::string error;
  EXPECT_FALSE(parse_redis_url("redis://:hunter2@cache:99999", error));
  EXPECT_EQ(error.find("hunter2"), std::string::npos) << "an error never shows the password: " << error;
  EXPECT_NE(error.find("redis://***@cache:99999"), std::string::npos) << error;
}

// ---- connections ----------------------------------------------------------

class RedisConnectionTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(redis.ok()) << redis.error(); }

  RedisAddress address(const std::string& suffix = "") const { return parsed(redis.url() + suffix); }

  /// Runs the loop until `done()` or `limit`; false on the time-out.
  bool run_until(const std::function<bool()>& done, std::chrono::milliseconds limit = 5000ms) {
    const auto deadline = Clock::now() + limit;
    while (!done()) {
      if (Clock::now() >= deadline) return false;
      if (io.stopped()) io.restart();
      if (io.run_one_for(20ms) == 0) std::this_thread::sleep_for(1ms);
    }
    return true;
  }
  /// Runs the loop for `duration`, whatever happens.
  void run_for(std::chrono::milliseconds duration) {
    run_until([] { return false; }, duration);
  }

  /// A connected connection, or nullptr (and a failure).
  std::shared_ptr<RedisConnection> connected(RedisConnection::Options options = {}, const std::string& suffix = "") {
    auto connection = RedisConnection::create(io.get_executor(), address(suffix), options);
    std::optional<std::string> result;
    connection->connect([&](const std::string& error) { result = error; });
    if (!run_until([&] { return result.has_value(); })) {
      ADD_FAILURE() << "connect did not finish";
      return nullptr;
    }
    if (!result->empty()) {
      ADD_FAILURE() << "connect failed: " << *result;
      return nullptr;
    }
    EXPECT_TRUE(connection->connected());
    return connection;
  }

  /// One command's reply, waited for; nullopt for nullptr (or no answer in 5 s).
  std::optional<RedisReply> ask(RedisConnection& connection, std::vector<std::string> args) {
    bool answered = false;
    std::optional<RedisReply> result;
    connection.command(std::move(args), [&](const RedisReply* reply) {
      answered = true;
      if (reply != nullptr) result = *reply;
    });
    EXPECT_TRUE(run_until([&] { return answered; })) << "no answer";
    return result;
  }

  boost::asio::io_context io;
  test::RedisProcess redis;
};

TEST_F(RedisConnectionTest, SetsAndGetsBinaryValuesOfAnySize) {
  auto connection = connected();
  ASSERT_TRUE(connection);

  const std::string key("face\0key\n", 9);
  const std::string small("\0a\r\n\0\xff\x80 end", 11);
  ASSERT_EQ(ask(*connection, {"SET", key, small})->text, "OK");
  const auto back = ask(*connection, {"GET", key});
  ASSERT_TRUE(back);
  EXPECT_EQ(back->type, RedisReply::Type::string);
  EXPECT_EQ(back->text, small) << "NULs, CR LF and high bytes both ways";

  std::string large(1 << 20, '\0');
  std::mt19937 random(7);
  for (auto& byte : large) byte = static_cast<char>(random());
  ASSERT_TRUE(ask(*connection, {"SET", "large", large})->is_status("OK"));
  const auto large_back = ask(*connection, {"GET", "large"});
  ASSERT_TRUE(large_back);
  EXPECT_EQ(large_back->text.size(), large.size());
  EXPECT_TRUE(large_back->text == large) << "1 MiB of random bytes both ways";

  EXPECT_TRUE(ask(*connection, {"GET", "no such key"})->is_nil());
  EXPECT_EQ(ask(*connection, {"INCRBY", "count", "41"})->integer, 41);
  const auto refused = ask(*connection, {"NOSUCHCOMMAND", "x"});
  ASSERT_TRUE(refused) << "an error is a reply, not a lost connection";
  EXPECT_TRUE(refused->is_error());
  EXPECT_NE(refused->text.find("unknown command"), std::string::npos) << refused->text;
  ASSERT_TRUE(ask(*connection, {"RPUSH", "list", "a", std::string("\0b", 2)}));
  const auto list = ask(*connection, {"LRANGE", "list", "0", "-1"});
  ASSERT_TRUE(list);
  ASSERT_EQ(list->type, RedisReply::Type::array);
  ASSERT_EQ(list->elements.size(), 2u);
  EXPECT_EQ(list->elements[1].text, std::string("\0b", 2));
  EXPECT_TRUE(connection->connected()) << "the error left the connection up";
}

TEST_F(RedisConnectionTest, SelectsTheDatabaseOfTheUrl) {
  auto zero = connected();
  auto three = connected({}, "/3");
  ASSERT_TRUE(zero && three);
  ASSERT_TRUE(ask(*three, {"SET", "where", "three"}));
  EXPECT_TRUE(ask(*zero, {"GET", "where"})->is_nil()) << "db 0 does not see db 3's keys";
  EXPECT_EQ(ask(*three, {"GET", "where"})->text, "three");
  EXPECT_NE(ask(*three, {"CLIENT", "INFO"})->text.find(" db=3 "), std::string::npos) << "Redis says so too";
}

TEST_F(RedisConnectionTest, ConnectsByNameTryingEachAddress) {
  // "localhost" may resolve to ::1 first, where this Redis does not listen.
  const auto by_name = parsed("redis://localhost:" + std::to_string(redis.port()));
  auto connection = RedisConnection::create(io.get_executor(), by_name, {2000ms, 3000ms, "facewire-test-node"});
  std::optional<std::string> result;
  connection->connect([&](const std::string& error) { result = error; });
  ASSERT_TRUE(run_until([&] { return result.has_value(); }));
  ASSERT_EQ(*result, "");
  const auto name = ask(*connection, {"CLIENT", "GETNAME"});
  ASSERT_TRUE(name);
  EXPECT_EQ(name->text, "facewire-test-node") << "CLIENT SETNAME at connect";
}

TEST_F(RedisConnectionTest, AnswersManyPipelinedCommandsInOrder) {
  auto connection = connected();
  ASSERT_TRUE(connection);
  constexpr int count = 20000;
  std::vector<long long> answers;
  answers.reserve(count);
  for (int i = 0; i < count; ++i)
    connection->command({"INCR", "sequence"}, [&](const RedisReply* reply) {
      answers.push_back(reply != nullptr ? reply->integer : -1);
    });
  // Nothing was written yet: the loop has not run. Every command waits in
  // hiredis' buffer, which back-pressure reads.
  EXPECT_EQ(connection->commands_waiting(), static_cast<std::size_t>(count));
  EXPECT_GE(connection->pending_output(), static_cast<std::size_t>(count) * 20);
  EXPECT_TRUE(answers.empty()) << "handlers are never called from command()";
  ASSERT_TRUE(run_until([&] { return answers.size() == count; }, 10000ms)) << answers.size() << " answers";
  for (int i = 0; i < count; ++i) ASSERT_EQ(answers[i], i + 1) << "answer " << i;
  EXPECT_EQ(connection->pending_output(), 0u);
  EXPECT_EQ(connection->commands_waiting(), 0u);
}

TEST_F(RedisConnectionTest, DeliversChannelAndPatternMessagesBetweenTwoConnections) {
  auto publisher = connected();
  auto subscriber = connected();
  ASSERT_TRUE(publisher && subscriber);
  std::vector<std::pair<std::string, std::string>> received;
  subscriber->on_message([&](std::string_view channel, std::string_view payload) {
    received.emplace_back(channel, payload);
  });
  subscriber->subscribe({"room:lobby", std::string("room:\0bin", 9)});
  subscriber->psubscribe({"node:*"});
  const auto subscribed = [&](const std::string& channel) {
    const auto reply = ask(*publisher, {"PUBSUB", "NUMSUB", channel});
    return reply && reply->elements.size() == 2 && reply->elements[1].integer == 1;
  };
  ASSERT_TRUE(run_until(
      [&] { return subscribed("room:lobby") && ask(*publisher, {"PUBSUB", "NUMPAT"})->integer == 1; }));

  const std::string payload = std::string("\0tick\0", 6) + std::string(100000, 'x');
  EXPECT_EQ(ask(*publisher, {"PUBLISH", "room:lobby", payload})->integer, 1);
  EXPECT_EQ(ask(*publisher, {"PUBLISH", std::string("room:\0bin", 9), "binary channel"})->integer, 1);
  EXPECT_EQ(ask(*publisher, {"PUBLISH", "node:7", "load 3"})->integer, 1);
  EXPECT_EQ(ask(*publisher, {"PUBLISH", "elsewhere", "nobody"})->integer, 0);
  ASSERT_TRUE(run_until([&] { return received.size() >= 3; }));
  ASSERT_EQ(received.size(), 3u);
  EXPECT_EQ(received[0].first, "room:lobby");
  EXPECT_TRUE(received[0].second == payload) << "a 100 kB payload with NULs, whole";
  EXPECT_EQ(received[1].first, std::string("room:\0bin", 9));
  EXPECT_EQ(received[2], std::make_pair(std::string("node:7"), std::string("load 3")))
      << "a pattern's message names the channel it was published on";

  // A subscriber takes no commands: nullptr, posted.
  bool refused = false;
  subscriber->command({"PING"}, [&](const RedisReply* reply) { refused = reply == nullptr; });
  EXPECT_FALSE(refused);
  ASSERT_TRUE(run_until([&] { return refused; }));

  subscriber->unsubscribe({"room:lobby"});
  ASSERT_TRUE(run_until([&] { return !subscribed("room:lobby"); }));
  EXPECT_EQ(ask(*publisher, {"PUBLISH", "room:lobby", "gone"})->integer, 0);
  EXPECT_EQ(ask(*publisher, {"PUBLISH", "node:8", "still here"})->integer, 1);
  ASSERT_TRUE(run_until([&] { return received.size() == 4; }));
  EXPECT_EQ(received[3].second, "still here");
  EXPECT_TRUE(subscriber->connected());
}

TEST_F(RedisConnectionTest, RedisKilledLosesTheConnectionOnceAfterEveryWaitingHandler) {
  auto connection = connected();
  auto subscriber = connected();
  ASSERT_TRUE(connection && subscriber);
  std::vector<std::string> events;
  connection->on_lost([&](const std::string& why) { events.push_back("lost: " + why); });
  int subscriber_lost = 0;
  subscriber->on_lost([&](const std::string&) { ++subscriber_lost; });
  subscriber->subscribe({"room:lobby"});
  // BLPOP on an empty list is never answered: three commands wait.
  for (int i = 0; i < 3; ++i)
    connection->command({"BLPOP", "empty", "0"},
                        [&, i](const RedisReply* reply) {
                          events.push_back(reply ? "reply" : "nullptr " + std::to_string(i));
                        });
  run_for(200ms);
  ASSERT_TRUE(events.empty());
  EXPECT_EQ(connection->commands_waiting(), 3u);

  redis.kill();
  ASSERT_TRUE(run_until([&] { return !events.empty() && events.back().rfind("lost", 0) == 0 && subscriber_lost > 0; }));
  run_for(200ms);
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0], "nullptr 0");
  EXPECT_EQ(events[1], "nullptr 1");
  EXPECT_EQ(events[2], "nullptr 2");
  EXPECT_NE(events[3].find("lost the connection to redis://127.0.0.1:" + std::to_string(redis.port())),
            std::string::npos)
      << events[3];
  EXPECT_EQ(subscriber_lost, 1);
  EXPECT_FALSE(connection->connected());
  EXPECT_EQ(connection->commands_waiting(), 0u);

  // After the loss: nullptr, posted; on_lost is not called again.
  bool answered = false;
  connection->command({"PING"}, [&](const RedisReply* reply) { answered = reply == nullptr; });
  EXPECT_FALSE(answered);
  ASSERT_TRUE(run_until([&] { return answered; }));
  connection->close();
  run_for(100ms);
  EXPECT_EQ(events.size(), 4u);
}

TEST_F(RedisConnectionTest, CloseCallsWaitingHandlersThenOnLost) {
  auto connection = connected();
  ASSERT_TRUE(connection);
  std::vector<std::string> events;
  connection->on_lost([&](const std::string& why) { events.push_back(why); });
  connection->command({"BLPOP", "empty", "0"},
                      [&](const RedisReply* reply) { events.push_back(reply ? "reply" : "nullptr"); });
  run_for(100ms);
  connection->close();
  EXPECT_TRUE(events.empty()) << "posted, not called from close()";
  ASSERT_TRUE(run_until([&] { return events.size() == 2; }));
  EXPECT_EQ(events[0], "nullptr");
  EXPECT_NE(events[1].find("closed by this node"), std::string::npos) << events[1];
}

TEST_F(RedisConnectionTest, ConnectingToADeadPortFailsSayingWhy) {
  const int port = redis.port();
  redis.kill();
  auto connection = RedisConnection::create(io.get_executor(), parsed("redis://127.0.0.1:" + std::to_string(port)));
  bool lost = false;
  connection->on_lost([&](const std::string&) { lost = true; });
  std::optional<std::string> result;
  const auto start = Clock::now();
  connection->connect([&](const std::string& error) { result = error; });
  EXPECT_FALSE(result) << "done is posted, not called from connect()";
  ASSERT_TRUE(run_until([&] { return result.has_value(); }));
  EXPECT_LT(Clock::now() - start, 1000ms) << "a refusal is not a time-out";
  EXPECT_NE(result->find("cannot connect to redis://127.0.0.1:" + std::to_string(port) + "/0"), std::string::npos)
      << *result;
  EXPECT_NE(result->find("refused"), std::string::npos) << *result;
  EXPECT_FALSE(connection->connected());
  run_for(100ms);
  EXPECT_FALSE(lost) << "on_lost is for established connections";

  // A name nobody can resolve fails too, without blocking the loop.
  auto nameless = RedisConnection::create(io.get_executor(), parsed("redis://no-such-host.invalid:6379"));
  result.reset();
  nameless->connect([&](const std::string& error) { result = error; });
  ASSERT_TRUE(run_until([&] { return result.has_value(); }));
  EXPECT_NE(result->find("cannot resolve the host name 'no-such-host.invalid'"), std::string::npos) << *result;
}

TEST_F(RedisConnectionTest, ConnectTimesOutAgainstAStoppedRedis) {
  redis.pause();  // the kernel still accepts; nobody answers the handshake
  auto connection = RedisConnection::create(io.get_executor(), address(), {300ms, 3000ms, ""});
  std::optional<std::string> result;
  const auto start = Clock::now();
  connection->connect([&](const std::string& error) { result = error; });
  ASSERT_TRUE(run_until([&] { return result.has_value(); }));
  const auto took = Clock::now() - start;
  redis.resume();
  EXPECT_NE(result->find("no answer within 300 ms"), std::string::npos) << *result;
  EXPECT_GE(took, 250ms);
  EXPECT_LT(took, 2500ms);
}

TEST_F(RedisConnectionTest, ReconnectsWithANewConnectionAfterRedisRestartsOnTheSamePort) {
  auto first = connected();
  ASSERT_TRUE(first);
  bool lost = false;
  first->on_lost([&](const std::string&) { lost = true; });
  ASSERT_TRUE(ask(*first, {"SET", "before", "restart"}));

  redis.stop();  // SIGTERM: Redis closes its clients
  ASSERT_TRUE(run_until([&] { return lost; }));
  EXPECT_FALSE(first->connected());
  ASSERT_TRUE(redis.start()) << redis.error();

  auto second = connected();
  ASSERT_TRUE(second) << "a new connection to the same address";
  EXPECT_TRUE(ask(*second, {"GET", "before"})->is_nil()) << "no persistence: a restarted Redis is empty";
  EXPECT_TRUE(ask(*second, {"SET", "after", "restart"})->is_status("OK"));
}

TEST_F(RedisConnectionTest, CommandTimeoutLosesTheConnectionToAStoppedRedis) {
  auto connection = connected({2000ms, 500ms, ""});
  auto subscriber = connected({2000ms, 500ms, ""});
  ASSERT_TRUE(connection && subscriber);
  std::optional<std::string> lost;
  Clock::time_point lost_at;
  bool handler_got_nullptr = false;
  connection->on_lost([&](const std::string& why) {
    lost = why;
    lost_at = Clock::now();
  });
  std::optional<std::string> subscriber_lost;
  subscriber->on_lost([&](const std::string& why) { subscriber_lost = why; });

  // Answered commands keep it up past the time-out.
  for (int i = 0; i < 8; ++i) {
    ASSERT_TRUE(ask(*connection, {"PING"}));
    run_for(100ms);
  }
  EXPECT_TRUE(connection->connected());

  redis.pause();
  const auto sent = Clock::now();
  connection->command({"PING"}, [&](const RedisReply* reply) { handler_got_nullptr = reply == nullptr; });
  subscriber->subscribe({"room:lobby"});  // its confirmation never comes either
  ASSERT_TRUE(run_until([&] { return lost && subscriber_lost; }, 5000ms));
  redis.resume();
  EXPECT_TRUE(handler_got_nullptr);
  EXPECT_NE(lost->find("no answer within 500 ms"), std::string::npos) << *lost;
  EXPECT_NE(subscriber_lost->find("no answer within 500 ms"), std::string::npos) << *subscriber_lost;
  EXPECT_GE(lost_at - sent, 450ms);
  EXPECT_LT(lost_at - sent, 3000ms);
  EXPECT_FALSE(connection->connected());
}

TEST_F(RedisConnectionTest, DestroyingAConnectionWithCommandsInFlightIsClean) {
  auto counter = std::make_shared<int>(0);
  int answered_before = 0;
  {
    auto connection = connected();
    ASSERT_TRUE(connection);
    for (int i = 0; i < 1000; ++i)
      connection->command({"SET", "key" + std::to_string(i), std::string(1000, 'v')},
                          [counter](const RedisReply*) { ++*counter; });
    // Never answered, and holds back the commands after it.
    connection->command({"BLPOP", "empty", "0"}, [counter](const RedisReply*) { ++*counter; });
    for (int i = 0; i < 100; ++i) connection->command({"PING"}, [counter](const RedisReply*) { ++*counter; });
    ASSERT_TRUE(run_until([&] { return *counter == 1000; }));
    EXPECT_EQ(connection->commands_waiting(), 101u);
    answered_before = *counter;
  }
  EXPECT_EQ(counter.use_count(), 1) << "every handler was released with the connection";
  run_for(200ms);
  EXPECT_EQ(*counter, answered_before) << "handlers of a destroyed connection are dropped uncalled";

  // Destroyed while connecting, and while resolving a name.
  for (const std::string& url : {redis.url(), "redis://localhost:" + std::to_string(redis.port())}) {
    auto connection = RedisConnection::create(io.get_executor(), parsed(url));
    bool done = false;
    connection->connect([&](const std::string&) { done = true; });
    io.poll();
    connection.reset();
    run_for(100ms);
    EXPECT_FALSE(done);
  }

  // The last reference dropped by a handler: the connection goes once the
  // handlers being run return.
  auto connection = connected();
  ASSERT_TRUE(connection);
  int answered = 0;
  std::weak_ptr<RedisConnection> weak = connection;
  for (int i = 0; i < 10; ++i)
    connection->command({"PING"}, [&](const RedisReply*) {
      ++answered;
      connection.reset();
    });
  ASSERT_TRUE(run_until([&] { return weak.expired(); }));
  run_for(100ms);
  EXPECT_GE(answered, 1);
  EXPECT_TRUE(redis.ok());
}

}  // namespace
}  // namespace fw::server
