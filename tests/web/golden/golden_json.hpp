#pragma once
// The browser's golden files: JSON that the C++ code writes (inputs and the
// C++ outputs), committed under tests/vectors/<name>/<name>.json, which a
// node test runs the browser's port on. Numbers are written as the doubles
// of the C++ values (floats widened exactly), so a file read back compares
// equal, value for value, with what the C++ computes now.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fw::test::web_golden {

/// One golden file: its name (folder and file under tests/vectors) and the
/// C++ that makes it.
struct GoldenSet {
  std::string name;
  std::function<nlohmann::json()> make;
};

/// Every golden file of the browser's ports.
const std::vector<GoldenSet>& golden_sets();

/// `root`/<name>/<name>.json.
std::filesystem::path golden_path(const std::filesystem::path& root, const std::string& name);

/// Writes `value` there (folders made), indented, ending in a newline.
void write_golden(const std::filesystem::path& path, const nlohmann::json& value);

/// The file's JSON; a discarded value when it is missing or broken.
nlohmann::json read_golden(const std::filesystem::path& path);

/// Where `expected` and `actual` first differ ("/cases/3/step: "stop" vs
/// "next_server""), or "" when they are equal.
std::string first_difference(const nlohmann::json& expected, const nlohmann::json& actual);

}  // namespace fw::test::web_golden
