#pragma once
// Which live connection holds each join token: with --auth-secret, a token
// admits one person at a time (PROTOCOL.md 9.2). A connection that shows
// the holder's resume key (from its welcome) is the same person back after
// a drop the server has not noticed yet: it takes the token over. Thread-safe.
#include <chrono>
#include <functional>
#include <map>
#include <vector>
#include <memory>
#include <mutex>
#include <string>

namespace fw::server {

class ClientSession;

struct TokenClaim {
  bool granted = false;
  /// The live connection that held the token and gave way to a resume; to be closed.
  std::shared_ptr<ClientSession> replaced;
  /// In a cluster: the node whose connection held it and gave way (it is told to close it).
  std::string replaced_on;
};

/// What a cluster node tells the others of a token (cluster_limits.hpp):
/// held with the holder's resume key, or let go. Hashes only.
struct TokenNews {
  std::string token_hash;
  std::string resume_hash;  ///< empty: let go
  std::string taken_from;   ///< the node whose connection gave way to a resume, if any
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

  // Cluster: one person per token across nodes. Holds other nodes report
  // last a few seconds unless reported again.
  using Clock = std::chrono::steady_clock;
  /// Called (outside the lock) whenever a token is taken or let go here.
  void on_news(std::function<void(const TokenNews&)> observer);
  void remote_news(const std::string& node, const TokenNews& news, Clock::time_point until);
  /// Every token held here, as news (for the others' refresh).
  std::vector<TokenNews> held_here() const;
  /// Another node's connection took the token over with the resume key:
  /// the connection here that held it gives way (returned, to be closed).
  std::shared_ptr<ClientSession> give_way(const std::string& token_hash);

 private:
  struct Holder {
    std::weak_ptr<ClientSession> session;
    std::string resume;
  };
  struct RemoteHold {
    std::string node;
    std::string resume_hash;
    Clock::time_point until;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Holder> holders_;
  std::map<std::string, RemoteHold> remote_;  ///< by token hash
  std::function<void(const TokenNews&)> observer_;
};

}  // namespace fw::server
