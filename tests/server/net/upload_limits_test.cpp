// Uploads against the limits that keep one client, or many addresses
// together, from taking the server's memory or its photo preparation
// (server/PROTOCOL.md, "Limits"): an upload is refused from its header,
// before its body is read, when its address is over its rate or its
// declared bytes would take the address's or the server's bytes in flight
// (counted as received) past their share, or when the photo queue is full;
// each refusal says when to try again (Retry-After), and other addresses
// still upload. The real server on loopback sockets; other clients connect
// from 127.0.0.2 and up, and from several /24s (127.0.1.x, 127.0.2.x).
// Dribbled bodies and photo bombs: upload_starvation_test.cpp.
#include <chrono>
#include <future>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "test_paths.hpp"
#include "upload_client.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using namespace fw::test;

// One address starts many 4 MiB uploads and sends most of each body, as if
// it would finish them: only its share is admitted and held; the rest are
// refused from their header at once, and the server's memory stays near
// that share. Another address still uploads its photo meanwhile.
TEST(UploadLimits, UploadsHeldOpenHoldNoMoreThanTheAddressesShare) {
  RunningServer server("--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  std::this_thread::sleep_for(500ms);
  const long rss_before = server.rss_kb();
  constexpr int kUploads = 16;
  const std::string most_of_a_body(3 * kMiB, '\xff');
  Sockets held;
  int admitted = 0, refused = 0;
  for (int i = 0; i < kUploads; ++i) {
    const int fd = connect_from("127.0.0.1", server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 4 * kMiB)));
    // The header alone decides: a refusal comes before any of the body.
    if (const auto reply = answer_within(fd, 1500ms)) {
      ++refused;
      EXPECT_TRUE(reply->status == 429 || reply->status == 503) << reply->status << " " << reply->body;
      EXPECT_GE(retry_after(*reply), 1) << reply->headers;
      EXPECT_NE(reply->body.find("try again in"), std::string::npos) << reply->body;
      continue;
    }
    ++admitted;
    ASSERT_TRUE(send_all(fd, most_of_a_body)) << "upload " << i;
    // Bytes count as they are received: a moment for the server to read them.
    std::this_thread::sleep_for(300ms);
  }
  std::this_thread::sleep_for(500ms);
  const long grown_mib = (server.rss_kb() - rss_before) / 1024;
  // The address's share is 8 MiB: two uploads of 4 MiB.
  EXPECT_LE(admitted, 2);
  EXPECT_EQ(refused, kUploads - admitted);
  EXPECT_LT(grown_mib, 20) << "held " << kUploads << " uploads of which " << admitted << " admitted";
  EXPECT_GE(refusals(server, "upload_bytes"), 1);

  // Another client, from another address, is not held up.
  const std::string photo = read_bytes(test::test_photo("grace_hopper.jpg"));
  const auto other = upload_from("127.0.0.2", server.http_port(), "image/jpeg", photo);
  EXPECT_EQ(other.status, 201) << other.body;
}

// Uploads admitted together from one address are held to its share (8 MiB)
// as their bytes arrive: three are admitted from their headers (each fits
// beside what the others have sent so far), and the one whose bytes would
// take the address past its share is refused 429 while its body comes,
// with Retry-After, and closed. No pace (0): bodies stay open meanwhile.
TEST(UploadLimits, BytesReceivedAreHeldToTheAddressesShareWhileBodiesCome) {
  RunningServer server("--no-demo-room --min-upload-bytes-per-second 0");
  ASSERT_GT(server.http_port(), 0);
  Sockets held;
  std::vector<int> fds;
  for (int i = 0; i < 3; ++i) {
    const int fd = connect_from("127.0.6.1", server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    fds.push_back(fd);
  }
  ASSERT_TRUE(send_all(fds[0], upload_header("image/jpeg", 4 * kMiB) + std::string(3 * kMiB, '\xff')));
  std::this_thread::sleep_for(300ms);  // 3 MiB received and counted
  // 3 + 4 declared fit in 8: both admitted, neither has sent a byte yet.
  ASSERT_TRUE(send_all(fds[1], upload_header("image/jpeg", 4 * kMiB)));
  ASSERT_TRUE(send_all(fds[2], upload_header("image/jpeg", 4 * kMiB)));
  EXPECT_FALSE(answer_within(fds[1], 300ms)) << "admitted from its header";
  EXPECT_FALSE(answer_within(fds[2], 300ms)) << "admitted from its header";
  ASSERT_TRUE(send_all(fds[1], std::string(3 * kMiB, '\xff')));
  std::this_thread::sleep_for(300ms);  // 6 MiB held now
  ASSERT_TRUE(send_all(fds[2], std::string(3 * kMiB, '\xff')));
  const auto refused = answer_within(fds[2], 5s);
  ASSERT_TRUE(refused) << "the body past the address's share is answered while it comes";
  EXPECT_EQ(refused->status, 429) << refused->body;
  EXPECT_GE(retry_after(*refused), 1) << refused->headers;
  EXPECT_NE(refused->body.find("send one photo at a time"), std::string::npos) << refused->body;
  EXPECT_FALSE(answer_within(fds[0], 100ms)) << "the others still come";
  EXPECT_FALSE(answer_within(fds[1], 100ms)) << "the others still come";
  EXPECT_EQ(refusals(server, "upload_bytes"), 1);
}

// Many addresses together hold no more than the server's share (64 MiB),
// counted in bytes received: each upload sends 3 of the 4 MiB it declares,
// and an upload is admitted while its 4 MiB would still fit beside what the
// others sent. No pace (0), so that the bodies left waiting are not closed
// before the count is done.
TEST(UploadLimits, ManyAddressesTogetherHoldNoMoreThanTheServersShare) {
  RunningServer server("--no-demo-room --min-upload-bytes-per-second 0");
  ASSERT_GT(server.http_port(), 0);
  Sockets held;
  int admitted = 0, unavailable = 0;
  for (int i = 0; i < 24; ++i) {
    const int fd = connect_from("127.0." + std::to_string(1 + i / 8) + "." + std::to_string(10 + i), server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 4 * kMiB)));
    if (const auto reply = answer_within(fd, 300ms)) {
      EXPECT_EQ(reply->status, 503) << reply->body;
      EXPECT_GE(retry_after(*reply), 1) << reply->headers;
      ++unavailable;
      continue;
    }
    ++admitted;
    ASSERT_TRUE(send_all(fd, std::string(3 * kMiB, '\xff')));
    std::this_thread::sleep_for(150ms);  // read and counted
  }
  // 3 MiB received from each of 21 uploads leave no room for 4 more.
  EXPECT_EQ(admitted, 21);
  EXPECT_EQ(unavailable, 3);
  EXPECT_EQ(refusals(server, "upload_bytes"), 3);
}

// The rate is counted from the header: the seventh upload within a minute
// is refused before its body is sent, however large the body would be.
TEST(UploadLimits, TheSeventhUploadWithinAMinuteIsRefusedBeforeItsBody) {
  RunningServer server("--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  Sockets held;
  for (int i = 0; i < 6; ++i) {
    const int fd = connect_from("127.0.0.3", server.http_port());
    ASSERT_GE(fd, 0);
    held.fds.push_back(fd);
    ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 1000)));
    EXPECT_FALSE(answer_within(fd, 300ms)) << "upload " << i << " is admitted and its body awaited";
  }
  const int fd = connect_from("127.0.0.3", server.http_port());
  ASSERT_GE(fd, 0);
  held.fds.push_back(fd);
  ASSERT_TRUE(send_all(fd, upload_header("image/jpeg", 1000)));
  const auto refused = answer_within(fd, 5s);
  ASSERT_TRUE(refused) << "no answer before the body";
  EXPECT_EQ(refused->status, 429) << refused->body;
  const int wait = retry_after(*refused);
  // Six a minute, six at once: the next in ten seconds.
  EXPECT_GE(wait, 1);
  EXPECT_LE(wait, 10);
  std::smatch said;
  ASSERT_TRUE(std::regex_search(refused->body, said, std::regex("try again in (\\d+) seconds?"))) << refused->body;
  EXPECT_EQ(std::stoi(said[1]), wait) << "the body and the header agree";
  EXPECT_EQ(refusals(server, "upload_rate"), 1);
  // Another address has its own rate.
  const int other = connect_from("127.0.0.4", server.http_port());
  held.fds.push_back(other);
  ASSERT_TRUE(send_all(other, upload_header("image/jpeg", 1000)));
  EXPECT_FALSE(answer_within(other, 300ms));
}

/// A photo that is slow to prepare: a large flat picture (nine megapixels)
/// in few bytes, which the preparer decodes and searches for a face.
std::string slow_photo() {
  std::vector<std::uint8_t> png;
  cv::imencode(".png", cv::Mat(3000, 3000, CV_8UC3, cv::Scalar(120, 130, 140)), png);
  return {png.begin(), png.end()};
}

// Slow photos from several addresses at once, with room for one waiting
// photo: those beyond it are answered 503 with Retry-After rather than
// queued without bound, and the server takes photos again once it has room.
TEST(UploadLimits, AFullPhotoQueueIsAnsweredAndTheServerRecovers) {
  RunningServer server("--no-demo-room --photo-queue 1 --photo-threads 1");
  ASSERT_GT(server.http_port(), 0);
  const std::string slow = slow_photo();
  std::vector<std::future<test::HttpReply>> replies;
  for (int i = 0; i < 6; ++i)
    replies.push_back(std::async(std::launch::async, [&, i] {
      return upload_from("127.0.2." + std::to_string(10 + i), server.http_port(), "image/png", slow);
    }));
  int unavailable = 0, prepared = 0;
  for (auto& reply : replies) {
    const auto answer = reply.get();
    if (answer.status == 503) {
      ++unavailable;
      EXPECT_GE(retry_after(answer), 1) << answer.headers;
      EXPECT_NE(answer.body.find("photos waiting"), std::string::npos) << answer.body;
    } else {
      ++prepared;
      EXPECT_EQ(answer.status, 422) << "no face in a flat picture: " << answer.body;
    }
  }
  EXPECT_GE(unavailable, 1);
  EXPECT_GE(prepared, 1);
  EXPECT_EQ(refusals(server, "photo_queue_full"), unavailable);

  const std::string photo = read_bytes(test::test_photo("grace_hopper.jpg"));
  const auto later = upload_from("127.0.2.30", server.http_port(), "image/jpeg", photo);
  EXPECT_EQ(later.status, 201) << later.body;
}


}  // namespace
}  // namespace fw::server
