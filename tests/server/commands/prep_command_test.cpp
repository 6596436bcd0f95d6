// facewire-server prep and facewire-client render --avatar, run as a person
// runs them on the astronaut portrait and on bad input.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <png.h>

#include "photo_variants.hpp"
#include "run_command.hpp"

namespace fw::server {
namespace {

using test::bin;
using test::run_command;

const std::filesystem::path kDir = std::filesystem::temp_directory_path() / ("facewire_prep_" + std::to_string(::getpid()));

class PrepCommandTest : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directories(kDir); }
  void TearDown() override { std::filesystem::remove_all(kDir); }
};

bool png_size(const std::filesystem::path& path, unsigned& width, unsigned& height) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) return false;
  width = png.width, height = png.height;
  png_image_free(&png);
  return true;
}

TEST_F(PrepCommandTest, PreparesTheAstronautAndTheClientRendersHer) {
  const auto package = kDir / "eileen.fwa", sheet = kDir / "sheet.png", render = kDir / "render.png";
  const auto prep = run_command(bin("facewire-server") + " prep " + test::astronaut_path() + " -o " + package.string() +
                                " --preview " + sheet.string());
  ASSERT_EQ(prep.status, 0) << prep.output;
  EXPECT_NE(prep.output.find("1 face(s) found"), std::string::npos) << prep.output;
  EXPECT_LE(std::filesystem::file_size(package), 24u * 1024);
  unsigned w = 0, h = 0;
  ASSERT_TRUE(png_size(sheet, w, h));
  EXPECT_EQ(w, 960u) << "three panels side by side";
  EXPECT_EQ(h, 320u + 3 * 160u) << "over three rows of the contact sheet, six to a row";

  const auto client = run_command(bin("facewire-client") + " render --avatar " + package.string() + " -o " +
                                  render.string() + " --size 300x200");
  ASSERT_EQ(client.status, 0) << client.output;
  ASSERT_TRUE(png_size(render, w, h));
  EXPECT_EQ(w, 300u);
  EXPECT_EQ(h, 200u);
}

TEST_F(PrepCommandTest, BadPhotoIsExplainedAndNothingIsWritten) {
  const auto text = kDir / "notes.txt", package = kDir / "x.fwa", sheet = kDir / "x.png";
  { std::ofstream(text) << "not a photo"; }
  const auto result = run_command(bin("facewire-server") + " prep " + text.string() + " -o " + package.string() +
                                  " --preview " + sheet.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("not an image"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(package));
  EXPECT_FALSE(std::filesystem::exists(sheet));
}

TEST_F(PrepCommandTest, MissingPhotoAndModelAreExplained) {
  auto result = run_command(bin("facewire-server") + " prep /no/photo.jpg -o " + (kDir / "x.fwa").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("/no/photo.jpg: no such file"), std::string::npos) << result.output;
  result = run_command(bin("facewire-server") + " prep " + test::astronaut_path() + " -o " + (kDir / "x.fwa").string() +
                       " --landmark-model /no/model.dat");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("libdlib-data"), std::string::npos) << result.output;
}

TEST_F(PrepCommandTest, ClientRefusesADamagedPackage) {
  const auto package = kDir / "eileen.fwa";
  ASSERT_EQ(run_command(bin("facewire-server") + " prep " + test::astronaut_path() + " -o " + package.string()).status, 0);
  std::filesystem::resize_file(package, std::filesystem::file_size(package) - 100);
  const auto result = run_command(bin("facewire-client") + " render --avatar " + package.string() + " -o " +
                                  (kDir / "r.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("bad avatar package"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(kDir / "r.png"));
}

}  // namespace
}  // namespace fw::server
