#pragma once
// A plain, blocking Redis connection for the few calls that must finish
// before their caller goes on: an upload is answered only once its avatar is
// in Redis (so that nothing uploaded is lost with its node), and a node
// that lacks an avatar fetches it while it looks it up. Used from worker
// and photo threads, never from the node's I/O loop; one call at a time
// (a mutex). Everything else a node says to Redis goes through the
// asynchronous RedisConnection.
#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "redis_reply.hpp"
#include "redis_url.hpp"

struct redisContext;  // hiredis

namespace fw::server {

class RedisBlocking {
 public:
  RedisBlocking(RedisAddress address, std::chrono::milliseconds timeout);
  ~RedisBlocking();
  RedisBlocking(const RedisBlocking&) = delete;
  RedisBlocking& operator=(const RedisBlocking&) = delete;

  /// The reply, or nullopt when Redis did not answer in time (the
  /// connection is made again at a later call, at most once a second).
  std::optional<RedisReply> command(const std::vector<std::string>& args);

 private:
  bool connect_locked();

  RedisAddress address_;
  std::chrono::milliseconds timeout_;
  std::mutex mutex_;
  redisContext* context_ = nullptr;
  std::chrono::steady_clock::time_point last_attempt_{};
};

}  // namespace fw::server
