#include "fw/photo/landmark_model.hpp"

#include <cstdlib>
#include <fstream>

namespace fw::photo {

std::optional<std::filesystem::path> find_landmark_model(const std::optional<std::filesystem::path>& configured,
                                                         std::filesystem::path& tried) {
  if (configured) tried = *configured;
  else if (const char* env = std::getenv("FACEWIRE_LANDMARK_MODEL"); env && *env) tried = env;
  else tried = kDefaultLandmarkModel;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(tried, ec)) return std::nullopt;
  if (!std::ifstream(tried, std::ios::binary)) return std::nullopt;
  return tried;
}

}  // namespace fw::photo
