#pragma once
// Reading and writing whole files, bounded, for packages and photos.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fw::model {

/// Reads `path` if it is a regular file of at most `max_bytes`.
/// @return false and `error` (naming the path, saying what is wrong) otherwise
bool read_file(const std::filesystem::path& path, std::size_t max_bytes, std::vector<std::uint8_t>& bytes,
               std::string& error);

/// Writes `bytes` to `path` atomically: into a temporary file beside it, then
/// renamed over it, so a failure never leaves a partial file behind.
bool write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes, std::string& error);
/// The same for text (the tools' assets and corpora).
bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string& error);

}  // namespace fw::model
