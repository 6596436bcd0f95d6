#pragma once
// Files written so that a crash or a power cut at any moment leaves either
// the old file or the new one, whole, never a part of one: the bytes go to a
// temporary file of its own in the same directory, are flushed to the disk
// (fsync), and the file is renamed over the old one; the directory is then
// flushed too, so that the rename itself survives a power cut. Writers of
// the same path at once each use their own temporary file (the last rename
// wins), so two threads storing the same avatar do not tear each other's.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace fw::server {

/// Whether a write waits for the disk: `unsynced` still renames into place
/// whole, but a power cut may lose it; for files made again at every start.
enum class Durability { synced, unsynced };

/// Writes `bytes` to `path` as above; false and `error` (what failed, for
/// the log) when it cannot, leaving `path` as it was and no temporary file.
bool write_file_durably(const std::filesystem::path& path, std::span<const std::uint8_t> bytes, std::string& error,
                        Durability durability = Durability::synced);

/// Whether `name` (a file name, no directory) is one of the temporary files
/// write_file_durably makes, or that model::write_file_atomically made.
bool is_temporary_file_name(const std::string& name);

/// Removes the temporary files a crash left behind in `directory`, those
/// untouched for ten minutes (another process may be writing a newer one);
/// how many.
std::size_t remove_temporary_files(const std::filesystem::path& directory);

}  // namespace fw::server
