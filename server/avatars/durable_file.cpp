#include "durable_file.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace fw::server {
namespace {

constexpr std::string_view kTemporaryMark = ".tmp-";     // .NAME.tmp-XXXXXX (mkstemp)
constexpr std::string_view kOldTemporaryMark = ".partial-";  // NAME.partial-PID (write_file_atomically)

std::string system_error(const char* what, const std::filesystem::path& path) {
  return std::string(what) + " " + path.string() + ": " + std::strerror(errno);
}

bool write_all(int fd, std::span<const std::uint8_t> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return true;
}

/// Flushes the directory's entries, so that a rename into it is on the disk.
bool sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  return synced;
}

}  // namespace

bool write_file_durably(const std::filesystem::path& path, std::span<const std::uint8_t> bytes, std::string& error,
                        Durability durability) {
  const bool sync = durability == Durability::synced;
  const std::filesystem::path directory = path.parent_path();
  const std::string name = "." + path.filename().string() + std::string(kTemporaryMark) + "XXXXXX";
  std::string temporary = (directory / name).string();
  const int fd = ::mkostemp(temporary.data(), O_CLOEXEC);
  if (fd < 0) {
    error = system_error("cannot write", path) + " (check that the directory exists and is writable)";
    return false;
  }
  const auto fail = [&](const char* what) {
    error = system_error(what, path);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return false;
  };
  // mkstemp makes the file readable by the server's user alone, which
  // suits photos of people; it stays so.
  const bool written = write_all(fd, bytes) && (!sync || ::fsync(fd) == 0);
  if (!written) {
    ::close(fd);
    return fail("cannot write");
  }
  if (::close(fd) != 0) return fail("cannot write");
  if (::rename(temporary.c_str(), path.c_str()) != 0) return fail("cannot rename into");
  // The new file is in place; only a power cut before this flush could undo
  // the rename (leaving the old file, whole), so a failure is not an error.
  if (sync) sync_directory(directory);
  return true;
}

bool is_temporary_file_name(const std::string& name) {
  if (name.starts_with(".") && name.find(kTemporaryMark) != std::string::npos) return true;
  const auto old = name.rfind(kOldTemporaryMark);
  if (old == std::string::npos || old + kOldTemporaryMark.size() == name.size()) return false;
  for (std::size_t i = old + kOldTemporaryMark.size(); i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

std::size_t remove_temporary_files(const std::filesystem::path& directory) {
  std::size_t removed = 0;
  std::error_code ec;
  // Only files no write has touched for a while: another process sharing
  // the directory (a second server, a tool) may be writing one right now.
  const auto stale_before = std::filesystem::file_time_type::clock::now() - std::chrono::minutes(10);
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec)) {
    if (!entry.is_regular_file(ec) || !is_temporary_file_name(entry.path().filename().string())) continue;
    const auto written = entry.last_write_time(ec);
    if (ec || written > stale_before) continue;
    if (std::filesystem::remove(entry.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace fw::server
