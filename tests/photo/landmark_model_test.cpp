#include "fw/photo/landmark_model.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

namespace fw::photo {
namespace {

// deploy/install-deps.sh installs libdlib-data, which ships the model.
TEST(LandmarkModel, DebianModelIsInstalled) {
  ::unsetenv("FACEWIRE_LANDMARK_MODEL");
  std::filesystem::path tried;
  const auto found = find_landmark_model(std::nullopt, tried);
  ASSERT_TRUE(found.has_value()) << tried << " is missing: run deploy/install-deps.sh";
  EXPECT_GT(std::filesystem::file_size(*found), 50u * 1024 * 1024) << "the 68-point model is ~95 MB";
}

TEST(LandmarkModel, ConfiguredPathWinsAndMissingFileIsReported) {
  std::filesystem::path tried;
  EXPECT_FALSE(find_landmark_model(std::filesystem::path("/no/such/model.dat"), tried).has_value());
  EXPECT_EQ(tried, "/no/such/model.dat");
}

TEST(LandmarkModel, EnvironmentOverridesTheDefault) {
  ::setenv("FACEWIRE_LANDMARK_MODEL", "/no/env/model.dat", 1);
  std::filesystem::path tried;
  EXPECT_FALSE(find_landmark_model(std::nullopt, tried).has_value());
  EXPECT_EQ(tried, "/no/env/model.dat");
  ::unsetenv("FACEWIRE_LANDMARK_MODEL");
}

TEST(LandmarkModel, ADirectoryIsNotAModel) {
  std::filesystem::path tried;
  EXPECT_FALSE(find_landmark_model(std::filesystem::temp_directory_path(), tried).has_value());
}

}  // namespace
}  // namespace fw::photo
