#include "redis_blocking.hpp"

#include <hiredis/hiredis.h>
#include <spdlog/spdlog.h>

namespace fw::server {

namespace {
timeval to_timeval(std::chrono::milliseconds ms) {
  return {static_cast<time_t>(ms.count() / 1000), static_cast<suseconds_t>((ms.count() % 1000) * 1000)};
}
/// One command, its reply (hiredis' own; the caller frees it), or null when Redis did not answer.
redisReply* run(redisContext* context, const std::vector<std::string>& args) {
  std::vector<const char*> argv;
  std::vector<std::size_t> lengths;
  for (const auto& a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  return static_cast<redisReply*>(redisCommandArgv(context, static_cast<int>(argv.size()), argv.data(), lengths.data()));
}
}  // namespace

RedisBlocking::RedisBlocking(RedisAddress address, std::chrono::milliseconds timeout)
    : address_(std::move(address)), timeout_(timeout) {}

RedisBlocking::~RedisBlocking() {
  if (context_) redisFree(context_);
}

bool RedisBlocking::connect_locked() {
  if (context_) return true;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_attempt_ < std::chrono::seconds(1)) return false;  // Redis was not there a moment ago
  last_attempt_ = now;
  context_ = redisConnectWithTimeout(address_.host.c_str(), address_.port, to_timeval(timeout_));
  if (!context_ || context_->err) {
    if (context_) redisFree(context_);
    context_ = nullptr;
    return false;
  }
  redisSetTimeout(context_, to_timeval(timeout_));
  auto handshake = [&](const std::vector<std::string>& args) {
    redisReply* reply = run(context_, args);
    const bool ok = reply && reply->type != REDIS_REPLY_ERROR;
    if (reply) freeReplyObject(reply);
    return ok;
  };
  bool ok = true;
  if (!address_.password.empty())
    ok = address_.username.empty() ? handshake({"AUTH", address_.password})
                                   : handshake({"AUTH", address_.username, address_.password});
  if (ok && address_.db != 0) ok = handshake({"SELECT", std::to_string(address_.db)});
  if (!ok) {
    redisFree(context_);
    context_ = nullptr;
  }
  return ok;
}

std::optional<RedisReply> RedisBlocking::command(const std::vector<std::string>& args) {
  std::lock_guard lock(mutex_);
  if (!connect_locked()) return std::nullopt;
  redisReply* reply = run(context_, args);
  if (!reply) {
    spdlog::warn("Redis at {}:{} did not answer: {}", address_.host, address_.port, context_->errstr);
    redisFree(context_);
    context_ = nullptr;
    return std::nullopt;
  }
  RedisReply copy = copy_reply(*reply);
  freeReplyObject(reply);
  return copy;
}

}  // namespace fw::server
