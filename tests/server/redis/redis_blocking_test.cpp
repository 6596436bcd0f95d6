// The blocking Redis connection (redis_blocking.hpp) against a real
// redis-server that the test starts on a free loopback port
// (support/redis_process.hpp): the first call after Redis restarted is
// carried out, not lost on the connection the old server closed.
#include "redis_blocking.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "redis_process.hpp"
#include "redis_url.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;

RedisAddress address_of(const test::RedisProcess& redis) {
  std::string error;
  const auto address = parse_redis_url(redis.url(), error);
  EXPECT_TRUE(address) << error;
  return address.value_or(RedisAddress{});
}

TEST(RedisBlocking, TheFirstCallAfterRedisRestartsIsCarriedOut) {
  test::RedisProcess redis;
  ASSERT_TRUE(redis.ok()) << redis.error();
  RedisBlocking blocking(address_of(redis), 2000ms);
  const auto before = blocking.command({"SET", "k", "before"});
  ASSERT_TRUE(before && before->is_status("OK"));

  redis.stop();  // SIGTERM: Redis closes its clients, this one included
  ASSERT_TRUE(redis.start()) << redis.error();

  const auto after = blocking.command({"SET", "k", "after"});
  ASSERT_TRUE(after.has_value()) << "the call right after the restart was lost";
  EXPECT_TRUE(after->is_status("OK"));
  const auto read = blocking.command({"GET", "k"});
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->text, "after") << "the command reached the new Redis";
}

TEST(RedisBlocking, AGoneRedisIsReportedNotWaitedFor) {
  test::RedisProcess redis;
  ASSERT_TRUE(redis.ok()) << redis.error();
  RedisBlocking blocking(address_of(redis), 2000ms);
  ASSERT_TRUE(blocking.command({"PING"}).has_value());
  redis.stop();
  EXPECT_FALSE(blocking.command({"PING"}).has_value()) << "nothing answers on that port now";
}

}  // namespace
}  // namespace fw::server
