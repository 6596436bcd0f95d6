#pragma once
// Every avatar's face model (face_model.hpp), built from its package once
// per package version (the package's content hash, StoredAvatar::version)
// and shared by every room and seat that wears it.
//
// A build parses the package, fits the face and builds its tissue model:
// tens of milliseconds, so rooms build on the worker pool, never on their
// strand (OwnedRoom::join), and simulate the generic face until the
// avatar's own is ready (RoomSimulation::wear_face).
//
// Bounded: at most `capacity` models are kept for later. A model a room
// still holds is never dropped (its memory is the room's); beyond the
// bound, the models no room holds go, least recently asked for first.
// Thread-safe.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>

namespace fw::server {

struct FaceModel;

class FaceModels {
 public:
  /// About 0.7 MB a model (the tissue model and its constraints; the
  /// projective factorisation is the generic face's, shared): 256 are
  /// under 200 MB.
  static constexpr std::size_t kDefaultCapacity = 256;
  explicit FaceModels(std::size_t capacity = kDefaultCapacity);

  /// The model of package version `version`, if built and kept.
  std::shared_ptr<const FaceModel> find(const std::string& version);
  /// The model of the package `bytes` whose content hash is `version`:
  /// found, or built on the caller's thread and kept. Null, with `error`
  /// saying why, when the package does not parse.
  std::shared_ptr<const FaceModel> build(const std::string& version, std::span<const std::uint8_t> bytes,
                                         std::string& error);

  /// Models kept now; builds made (not found).
  std::size_t size() const;
  std::uint64_t builds() const;
  /// Run on the building thread before each build: tests hold builds back
  /// to see a room tick on meanwhile. Set before any build.
  void set_before_build(std::function<void()> hook) { before_build_ = std::move(hook); }

 private:
  void keep(const std::string& version, std::shared_ptr<const FaceModel> model);

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<std::string> recent_;  ///< versions, most recently asked for first
  struct Entry {
    std::shared_ptr<const FaceModel> model;
    std::list<std::string>::iterator place;
  };
  std::map<std::string, Entry> models_;
  std::uint64_t builds_ = 0;
  std::function<void()> before_build_;
};

}  // namespace fw::server
