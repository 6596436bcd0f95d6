#include "photo_worker.hpp"

#include <boost/asio/post.hpp>

#include "avatar_store.hpp"
#include "fw/photo/photo_limits.hpp"
#include "fw/photo/prepare_avatar.hpp"

namespace fw::server {

static_assert(kMaxStoredPhotoBytes == photo::kMaxPhotoBytes, "a stored photo is one the preparer takes");

PhotoWorker::PhotoWorker(std::string landmark_model) : landmark_model_(std::move(landmark_model)) {}

PhotoWorker::~PhotoWorker() { pool_.join(); }

void PhotoWorker::post(std::function<void()> job) { boost::asio::post(pool_, std::move(job)); }

photo::AvatarPreparer* PhotoWorker::preparer(photo::PrepError& error) {
  if (!preparer_) {
    const auto model = landmark_model_.empty() ? std::nullopt
                                               : std::optional<std::filesystem::path>(landmark_model_);
    preparer_ = photo::AvatarPreparer::create(model, error);
  }
  return preparer_.get();
}

}  // namespace fw::server
