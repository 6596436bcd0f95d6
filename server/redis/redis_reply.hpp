#pragma once
// A Redis reply as plain C++ values: a deep copy of what hiredis parsed, so
// that it outlives hiredis' own reply object (freed as soon as its callback
// returns) and users never see hiredis' types.
#include <string>
#include <string_view>
#include <vector>

struct redisReply;  // hiredis

namespace fw::server {

struct RedisReply {
  enum class Type { nil, status, error, integer, string, array };
  Type type = Type::nil;
  long long integer = 0;
  std::string text;                  ///< status, error, string (binary-safe)
  std::vector<RedisReply> elements;  ///< array

  bool is_error() const { return type == Type::error; }
  bool is_nil() const { return type == Type::nil; }
  /// "OK", "PONG" and the like: a status with this text.
  bool is_status(std::string_view expected) const { return type == Type::status && text == expected; }
};

/// A deep copy of a hiredis reply (RESP2: nil, status, error, integer,
/// string, array, nested to any depth).
RedisReply copy_reply(const redisReply& reply);

/// A short text for logs and errors: "(nil)", "OK", "ERR ...", "42",
/// "\"value\"" (printable, cut), "[3 elements]".
std::string describe(const RedisReply& reply);

}  // namespace fw::server
