#include "package_assembler.hpp"

namespace fw::client {

std::optional<AssembledPackage> PackageAssembler::add(const codec::PackageChunk& chunk, std::string& error) {
  const Key key{chunk.avatar, chunk.quality};
  if (chunk.total_bytes == 0 || chunk.total_bytes > kMaxAssembledBytes) {
    partial_.erase(key);
    error = "package of avatar " + std::to_string(chunk.avatar) + " announced with " +
            std::to_string(chunk.total_bytes) + " bytes; this client takes 1 .. " + std::to_string(kMaxAssembledBytes);
    return std::nullopt;
  }
  if (chunk.offset == 0) partial_[key] = Partial{chunk.total_bytes, {}};  // a new package restarts assembly
  const auto it = partial_.find(key);
  if (it == partial_.end()) return std::nullopt;  // the middle of a package whose start we missed
  Partial& partial = it->second;
  if (chunk.total_bytes != partial.total || chunk.offset != partial.bytes.size() ||
      chunk.data.size() > partial.total - partial.bytes.size()) {
    partial_.erase(it);
    error = "package chunk of avatar " + std::to_string(chunk.avatar) + " out of order or past its end; dropped";
    return std::nullopt;
  }
  partial.bytes.insert(partial.bytes.end(), chunk.data.begin(), chunk.data.end());
  if (partial.bytes.size() < partial.total) return std::nullopt;
  AssembledPackage done{chunk.avatar, chunk.quality, std::move(partial.bytes)};
  partial_.erase(it);
  return done;
}

void PackageAssembler::forget(std::uint32_t avatar) {
  std::erase_if(partial_, [avatar](const auto& entry) { return entry.first.first == avatar; });
}

}  // namespace fw::client
