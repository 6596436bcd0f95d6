#include "golden_json.hpp"

#include <fstream>
#include <stdexcept>

namespace fw::test::web_golden {

std::filesystem::path golden_path(const std::filesystem::path& root, const std::string& name) {
  return root / name / (name + ".json");
}

void write_golden(const std::filesystem::path& path, const nlohmann::json& value) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << value.dump(1) << '\n';
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

nlohmann::json read_golden(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(in, nullptr, false);
}

std::string first_difference(const nlohmann::json& expected, const nlohmann::json& actual) {
  const nlohmann::json patch = nlohmann::json::diff(expected, actual);
  if (patch.empty()) return "";
  const nlohmann::json& first = patch.front();
  const std::string path = first.value("path", std::string("/"));
  const std::string was = expected.contains(nlohmann::json::json_pointer(path))
                              ? expected.at(nlohmann::json::json_pointer(path)).dump()
                              : "(nothing)";
  const std::string now = first.contains("value") ? first.at("value").dump() : "(nothing)";
  return path + ": " + was + " in the file, " + now + " from the C++ now (" + first.value("op", std::string()) +
         ", " + std::to_string(patch.size()) + " difference(s))";
}

}  // namespace fw::test::web_golden
