#include "avatar_repreparation.hpp"

#include "fw/model/avatar_package.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "photo_worker.hpp"

namespace fw::server {
namespace {

// On the worker's thread. The options are the upload's (PhotoPreparation),
// so the avatar comes out as if its photo were uploaded today.
void prepare_again(AvatarStore& store, PhotoWorker& worker, const std::string& asset,
                   const std::vector<std::uint8_t>& photo) {
  photo::PrepError error;
  photo::AvatarPreparer* preparer = worker.preparer(error);
  const auto prepared = preparer ? preparer->prepare(photo, photo::PrepOptions{}, error) : std::nullopt;
  if (!prepared) return store.preparation_failed(asset, error.message);
  std::string why;
  store.replace(asset, model::serialize_avatar_package(prepared->package), why);  // logs and counts either way
}

}  // namespace

AvatarRepreparation::AvatarRepreparation(AvatarStore& store, PhotoWorker& worker) : store_(store) {
  // The jobs hold the store and the worker, not this object: both outlive
  // every job (the worker joins its jobs before it goes, the store after it).
  store_.set_repreparer([&store = store_, &worker](const std::string& asset, std::vector<std::uint8_t> photo) {
    worker.post([&store, &worker, asset, photo = std::move(photo)] { prepare_again(store, worker, asset, photo); });
  });
}

AvatarRepreparation::~AvatarRepreparation() { store_.set_repreparer(nullptr); }

}  // namespace fw::server
