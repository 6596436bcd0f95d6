#pragma once
// The packages the browser engine's tests read: sound ones (a real photo's,
// committed as the fuzz seed, and a synthetic fit without eye layer or head
// outline) and damaged ones, each with what the C++ reader says of it.
#include <cstdint>
#include <string>
#include <vector>

namespace fw::test {

struct GoldenPackage {
  std::string name;                ///< file name stem
  std::vector<std::uint8_t> bytes;
  bool sound = true;
  std::string error;               ///< parse_avatar_package's message when refused
  int refusal = 0;                 ///< its PackageRefusal
};

/// @param seed  the bytes of a sound package made from a photo
std::vector<GoldenPackage> golden_packages(const std::vector<std::uint8_t>& seed);

}  // namespace fw::test
