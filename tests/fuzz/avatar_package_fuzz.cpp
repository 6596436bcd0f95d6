// Fuzzes parse_avatar_package: any input gives an error message or a
// package that writes back to a package that parses again the same.
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

#include "fw/model/avatar_package.hpp"
#include "seed_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fw::model::AvatarPackage package;
  std::string error;
  const bool ok = fw::model::parse_avatar_package(std::span(data, size), package, error);
  if (ok == !error.empty()) std::abort();  // exactly one of: a package, or a reason
  if (!ok) fw::fuzz::seed_refused(error);
  if (ok) {
    fw::model::AvatarPackage again;
    if (!fw::model::parse_avatar_package(fw::model::serialize_avatar_package(package), again, error)) std::abort();
  }
  return 0;
}
