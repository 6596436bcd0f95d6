#include "token_holders.hpp"

#include <openssl/crypto.h>

#include "server_keys.hpp"

namespace fw::server {

namespace {
bool same_secret(const std::string& a, const std::string& b) {
  return !a.empty() && a.size() == b.size() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}
}  // namespace

TokenClaim TokenHolders::claim(const std::string& token, const std::shared_ptr<ClientSession>& session,
                               const std::string& presented_resume, const std::string& own_resume) {
  TokenClaim result;
  std::function<void(const TokenNews&)> observer;
  {
    std::lock_guard lock(mutex_);
    auto it = holders_.find(token);
    if (it != holders_.end()) {
      if (auto holder = it->second.session.lock()) {
        if (!same_secret(presented_resume, it->second.resume)) return result;
        result.replaced = std::move(holder);
      }
    }
    const std::string hash = secret_hash(token);
    if (const auto remote = remote_.find(hash); remote != remote_.end()) {
      if (remote->second.until > Clock::now()) {
        // Held by a connection on another node: only its resume key takes it over.
        if (!same_secret(secret_hash(presented_resume), remote->second.resume_hash)) return result;
        result.replaced_on = remote->second.node;
      }
      remote_.erase(remote);
    }
    holders_[token] = Holder{session, own_resume};
    result.granted = true;
    observer = observer_;
  }
  if (observer) observer({secret_hash(token), secret_hash(own_resume), result.replaced_on});
  return result;
}

void TokenHolders::release(const std::string& token, const ClientSession* session) {
  std::function<void(const TokenNews&)> observer;
  {
    std::lock_guard lock(mutex_);
    const auto it = holders_.find(token);
    if (it == holders_.end()) return;
    const auto holder = it->second.session.lock();
    if (holder && holder.get() != session) return;
    holders_.erase(it);
    observer = observer_;
  }
  if (observer) observer({secret_hash(token), "", ""});
}

std::size_t TokenHolders::held() const {
  std::lock_guard lock(mutex_);
  return holders_.size();
}

void TokenHolders::on_news(std::function<void(const TokenNews&)> observer) {
  std::lock_guard lock(mutex_);
  observer_ = std::move(observer);
}

void TokenHolders::remote_news(const std::string& node, const TokenNews& news, Clock::time_point until) {
  std::lock_guard lock(mutex_);
  const auto it = remote_.find(news.token_hash);
  if (news.resume_hash.empty()) {
    if (it != remote_.end() && it->second.node == node) remote_.erase(it);
    return;
  }
  remote_[news.token_hash] = RemoteHold{node, news.resume_hash, until};
}

std::vector<TokenNews> TokenHolders::held_here() const {
  std::lock_guard lock(mutex_);
  std::vector<TokenNews> held;
  for (const auto& [token, holder] : holders_)
    if (!holder.session.expired()) held.push_back({secret_hash(token), secret_hash(holder.resume), ""});
  return held;
}

std::shared_ptr<ClientSession> TokenHolders::give_way(const std::string& token_hash) {
  std::lock_guard lock(mutex_);
  for (auto it = holders_.begin(); it != holders_.end(); ++it)
    if (secret_hash(it->first) == token_hash) {
      auto holder = it->second.session.lock();
      holders_.erase(it);
      return holder;
    }
  return nullptr;
}

}  // namespace fw::server
