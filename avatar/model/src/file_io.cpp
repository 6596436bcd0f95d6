#include "fw/model/file_io.hpp"

#include <fstream>

#include <unistd.h>

namespace fw::model {

bool read_file(const std::filesystem::path& path, std::size_t max_bytes, std::vector<std::uint8_t>& bytes,
               std::string& error) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    error = path.string() + ": no such file";
    return false;
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = path.string() + ": " + ec.message();
    return false;
  }
  if (size > max_bytes) {
    error = path.string() + " is " + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) +
            " are accepted";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes.resize(size);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
    error = path.string() + ": cannot be read";
    return false;
  }
  return true;
}

bool write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes, std::string& error) {
  const std::filesystem::path temporary = path.string() + ".partial-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      error = "cannot write " + path.string() + " (check that the directory exists and is writable)";
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    error = "cannot write " + path.string() + ": " + ec.message();
    return false;
  }
  return true;
}

bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string& error) {
  return write_file_atomically(
      path, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), error);
}

}  // namespace fw::model
