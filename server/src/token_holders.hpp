#pragma once
// Which live connection holds each join token: with --auth-secret, a token
// admits one person at a time (PROTOCOL.md 9.2). A connection that shows
// the holder's resume key (from its welcome) is the same person back after
// a drop the server has not noticed yet: it takes the token over. Thread-safe.
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace fw::server {

class ClientSession;

struct TokenClaim {
  bool granted = false;
  /// The live connection that held the token and gave way to a resume; to be closed.
  std::shared_ptr<ClientSession> replaced;
};

class TokenHolders {
 public:
  /// `session` (whose resume key is `own_resume`) takes `token`, unless a
  /// live connection holds it and `presented_resume` is not that one's key.
  TokenClaim claim(const std::string& token, const std::shared_ptr<ClientSession>& session,
                   const std::string& presented_resume, const std::string& own_resume);
  /// `session` lets `token` go (if it still holds it).
  void release(const std::string& token, const ClientSession* session);
  std::size_t held() const;

 private:
  struct Holder {
    std::weak_ptr<ClientSession> session;
    std::string resume;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Holder> holders_;
};

}  // namespace fw::server
