#include "token_holders.hpp"

#include <openssl/crypto.h>

namespace fw::server {

TokenClaim TokenHolders::claim(const std::string& token, const std::shared_ptr<ClientSession>& session,
                               const std::string& presented_resume, const std::string& own_resume) {
  std::lock_guard lock(mutex_);
  TokenClaim result;
  auto it = holders_.find(token);
  if (it != holders_.end()) {
    if (auto holder = it->second.session.lock()) {
      const std::string& key = it->second.resume;
      const bool resumes = !presented_resume.empty() && presented_resume.size() == key.size() &&
                           CRYPTO_memcmp(presented_resume.data(), key.data(), key.size()) == 0;
      if (!resumes) return result;
      result.replaced = std::move(holder);
    }
  }
  holders_[token] = Holder{session, own_resume};
  result.granted = true;
  return result;
}

void TokenHolders::release(const std::string& token, const ClientSession* session) {
  std::lock_guard lock(mutex_);
  const auto it = holders_.find(token);
  if (it == holders_.end()) return;
  const auto holder = it->second.session.lock();
  if (!holder || holder.get() == session) holders_.erase(it);
}

std::size_t TokenHolders::held() const {
  std::lock_guard lock(mutex_);
  return holders_.size();
}

}  // namespace fw::server
