#pragma once
// Where a test finds the source tree (test photos, vectors, assets) and the
// build's programs. ctest passes both in the environment (tests/CMakeLists.txt)
// rather than compiling them in, so that no clone's absolute path reaches the
// compiler and its cache hits in every clone.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace fw::test {

/// `variable` from the environment or, when it is not set (a test or the
/// benchmark run by hand), `levels_up` folders above this executable: the
/// presets put programs in <source>/<build>/bin and tests in
/// <source>/<build>/tests.
inline std::string environment_path(const char* variable, int levels_up) {
  const char* value = std::getenv(variable);
  if (value != nullptr && *value != '\0') return value;
  std::error_code ec;
  auto path = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  for (int i = 0; i < levels_up; ++i) path = path.parent_path();
  if (ec || !std::filesystem::exists(path)) {
    std::fprintf(stderr, "%s is not set and cannot be guessed: set it\n", variable);
    std::exit(2);
  }
  return path.string();
}

/// The source tree's root.
inline std::string source_dir() { return environment_path("FW_SOURCE_DIR", 2); }

/// `relative` inside the source tree.
inline std::string source_path(const std::string& relative) { return source_dir() + "/" + relative; }

/// The test photos, committed under tests/data (see its README).
inline std::string test_photo(const std::string& file_name) { return source_path("tests/data/" + file_name); }

/// Path of an executable of this build (build/bin/NAME).
inline std::string bin(const std::string& name) {
  const char* dir = std::getenv("FW_BIN_DIR");
  if (dir != nullptr && *dir != '\0') return std::string(dir) + "/" + name;
  return environment_path("FW_BIN_DIR", 1) + "/bin/" + name;  // <build>/tests/.. or <build>/bin/..
}

}  // namespace fw::test
