#pragma once
// One photo preparer per test process: dlib's landmark model takes about
// 100 MB and a second or more to load, and every photo suite of a shard
// needs it, for preparing photos and for finding landmarks on renders.
#include <stdexcept>

#include "fw/photo/prepare_avatar.hpp"

namespace fw::test {

/// Loaded on first use from the default place; throws if it cannot be.
inline photo::AvatarPreparer& shared_preparer() {
  static photo::AvatarPreparer* preparer = [] {
    photo::PrepError error;
    auto loaded = photo::AvatarPreparer::create(std::nullopt, error);
    if (!loaded) throw std::runtime_error("the landmark model does not load: " + error.message);
    return loaded.release();  // lives as long as the process
  }();
  return *preparer;
}

}  // namespace fw::test
