#pragma once
// Puts an avatar's package back together from the chunks the server sends
// below the parameter stream (codec::PackageChunk): the preview first, the
// full package after it. Bounded: one package per avatar and quality in
// progress, each at most kMaxAssembledBytes.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::client {

/// The client parses packages of at most model::kMaxPackageBytes; larger
/// announcements are refused before anything is buffered.
inline constexpr std::uint32_t kMaxAssembledBytes = 512 * 1024;

struct AssembledPackage {
  std::uint32_t avatar = 0;
  codec::PackageChunk::Quality quality = codec::PackageChunk::Quality::preview;
  std::vector<std::uint8_t> bytes;
};

class PackageAssembler {
 public:
  /// Adds a chunk. Returns the package once its last chunk arrived; an
  /// out-of-order or inconsistent chunk drops that package (with `error`
  /// set) and the assembler waits for a chunk at offset 0 again.
  std::optional<AssembledPackage> add(const codec::PackageChunk& chunk, std::string& error);
  /// Forgets what arrived for an avatar (it left, or the connection dropped).
  void forget(std::uint32_t avatar);
  void clear() { partial_.clear(); }

 private:
  using Key = std::pair<std::uint32_t, codec::PackageChunk::Quality>;
  struct Partial {
    std::uint32_t total = 0;
    std::vector<std::uint8_t> bytes;
  };
  std::map<Key, Partial> partial_;
};

}  // namespace fw::client
