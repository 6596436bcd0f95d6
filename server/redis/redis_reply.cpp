#include "redis_reply.hpp"

#include <hiredis/hiredis.h>

#include "log_text.hpp"

namespace fw::server {

RedisReply copy_reply(const redisReply& reply) {
  RedisReply copy;
  switch (reply.type) {
    case REDIS_REPLY_STATUS:
      copy.type = RedisReply::Type::status;
      copy.text.assign(reply.str, reply.len);
      break;
    case REDIS_REPLY_ERROR:
      copy.type = RedisReply::Type::error;
      copy.text.assign(reply.str, reply.len);
      break;
    case REDIS_REPLY_INTEGER:
      copy.type = RedisReply::Type::integer;
      copy.integer = reply.integer;
      break;
    case REDIS_REPLY_STRING:
      copy.type = RedisReply::Type::string;
      copy.text.assign(reply.str, reply.len);
      break;
    case REDIS_REPLY_ARRAY:
      copy.type = RedisReply::Type::array;
      copy.elements.reserve(reply.elements);
      for (std::size_t i = 0; i < reply.elements; ++i) copy.elements.push_back(copy_reply(*reply.element[i]));
      break;
    default:  // REDIS_REPLY_NIL
      copy.type = RedisReply::Type::nil;
      break;
  }
  return copy;
}

std::string describe(const RedisReply& reply) {
  switch (reply.type) {
    case RedisReply::Type::nil: return "(nil)";
    case RedisReply::Type::status:
    case RedisReply::Type::error: return printable(reply.text, 200);
    case RedisReply::Type::integer: return std::to_string(reply.integer);
    case RedisReply::Type::string: {
      std::string text(1, '"');
      text.append(printable(reply.text, 60)).push_back('"');
      return text;
    }
    case RedisReply::Type::array: {
      std::string text(1, '[');
      text.append(std::to_string(reply.elements.size())).append(" elements]");
      return text;
    }
  }
  return "?";
}

}  // namespace fw::server
