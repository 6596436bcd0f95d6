#pragma once
// Stored avatars whose package is of another format or generic face than
// this build's, prepared again from the photo kept beside them, on the
// photo worker, and stored under the same id (avatar_store.hpp). The store
// hands them over when they are first asked for; meanwhile it answers that
// they are being prepared. Installed on the store for this object's life.
#include "avatar_store.hpp"

namespace fw::server {

class PhotoWorker;

class AvatarRepreparation {
 public:
  AvatarRepreparation(AvatarStore& store, PhotoWorker& worker);
  /// The store hands over no more avatars; those handed over still finish.
  ~AvatarRepreparation();
  AvatarRepreparation(const AvatarRepreparation&) = delete;
  AvatarRepreparation& operator=(const AvatarRepreparation&) = delete;

 private:
  AvatarStore& store_;
};

}  // namespace fw::server
