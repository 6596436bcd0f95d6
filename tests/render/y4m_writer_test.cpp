#include "fw/render/y4m_writer.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include <gtest/gtest.h>

namespace fw::render {
namespace {

TEST(Y4mWriter, ConvertsGreyAndPrimariesToFullRangeYuv) {
  model::RgbaImage image(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = 255, p[1] = 0, p[2] = 0, p[3] = 255;  // red
    }
  std::vector<std::uint8_t> planes;
  rgba_to_i420(image, planes);
  ASSERT_EQ(planes.size(), 6u);
  EXPECT_EQ(planes[0], 76);   // Y of red: 0.299 * 255
  EXPECT_EQ(planes[4], 85);   // Cb
  EXPECT_EQ(planes[5], 255);  // Cr
  for (auto& byte : image.pixels) byte = 128;
  rgba_to_i420(image, planes);
  EXPECT_EQ(planes[0], 128);
  EXPECT_EQ(planes[4], 128);
  EXPECT_EQ(planes[5], 128);
}

TEST(Y4mWriter, WritesAHeaderThenOneFramePerImage) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("facewire_y4m_writer_test_" + std::to_string(::getpid()) + ".y4m");
  std::string error;
  {
    auto writer = Y4mWriter::create(path.string(), 4, 2, 15, error);
    ASSERT_TRUE(writer) << error;
    model::RgbaImage frame(4, 2);
    ASSERT_TRUE(writer->write(frame, error)) << error;
    ASSERT_TRUE(writer->write(frame, error)) << error;
    EXPECT_FALSE(writer->write(model::RgbaImage(2, 2), error)) << "a frame of another size";
    EXPECT_NE(error.find("another size"), std::string::npos) << error;
  }
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = "YUV4MPEG2 W4 H2 F15:1 Ip A1:1 C420jpeg XCOLORRANGE=FULL\n";
  ASSERT_EQ(bytes.rfind(header, 0), 0u) << bytes.substr(0, 60);
  EXPECT_EQ(bytes.size(), header.size() + 2 * (6 + 8 + 2 + 2));
  std::filesystem::remove(path);
}

TEST(Y4mWriter, RefusesOddSizesAndUnwritablePaths) {
  std::string error;
  EXPECT_FALSE(Y4mWriter::create("/dev/null", 5, 4, 15, error));
  EXPECT_NE(error.find("even width and height, not 5x4"), std::string::npos) << error;
  EXPECT_FALSE(Y4mWriter::create("/no/such/dir/out.y4m", 4, 4, 15, error));
  EXPECT_NE(error.find("/no/such/dir/out.y4m: cannot open for writing"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::render
