// facewire-client join, run as a person runs it: the self view is the first
// frame, written before the upload and before any word from the server.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

#include "run_command.hpp"
#include "test_paths.hpp"

namespace fw::client {
namespace {

// A loopback port nobody listens on (bound, then released).
int closed_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  EXPECT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length), 0);
  ::close(fd);
  return ntohs(address.sin_port);
}

TEST(JoinSelfView, TheFirstFrameShowsTheOwnPhotoBeforeTheServerSaysAnything) {
  const auto dir = std::filesystem::temp_directory_path() / "facewire_join_self_view";
  std::filesystem::remove_all(dir);
  // Nobody answers: the upload fails (status 2), after the first frame.
  const auto result = test::run_command(test::bin("facewire-client") + " join ws://127.0.0.1:" +
                                        std::to_string(closed_port()) + "/ --room r --name Ada --photo " +
                                        test::test_photo("grace_hopper.jpg") + " --out " + dir.string() +
                                        " --size 320x180 --samples 0 -q");
  EXPECT_EQ(result.status, 2) << result.output;
  const auto first = dir / "frame_000001.png";
  ASSERT_TRUE(std::filesystem::exists(first)) << result.output;
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, first.c_str()));
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, rgb.data(), 0, nullptr));
  ASSERT_EQ(png.width, 320u);
  // The bottom right corner holds the photo; the rest is the empty room.
  const auto differs_from_room = [&](unsigned x, unsigned y) {
    const std::uint8_t* p = &rgb[(y * png.width + x) * 3];
    return std::abs(p[0] - 33) + std::abs(p[1] - 36) + std::abs(p[2] - 43) > 40;
  };
  int photo = 0, corner = 0, room = 0;
  for (unsigned y = 130; y < 172; ++y)
    for (unsigned x = 255; x < 312; ++x, ++corner) photo += differs_from_room(x, y) ? 1 : 0;
  for (unsigned y = 10; y < 100; ++y)
    for (unsigned x = 10; x < 200; ++x) room += differs_from_room(x, y) ? 1 : 0;
  EXPECT_GT(photo, corner * 3 / 4) << "the self view shows the photo";
  EXPECT_EQ(room, 0) << "nobody else is there yet";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fw::client
