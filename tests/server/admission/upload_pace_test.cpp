// The pace an upload's body must keep once it has started (upload_pace.hpp),
// with the time passed in: a body dribbled a byte a second is too slow after
// its free first window, one that keeps the pace never is however long it
// takes, one that stalls is too slow a window after its last bytes, and no
// pace at all (0) is never too slow.
#include "upload_pace.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using Clock = UploadPace::Clock;

constexpr std::size_t kPace = 16 * 1024;  // bytes a second
constexpr auto kWindow = 5s;

TEST(UploadPace, AByteASecondIsTooSlowOnceTheFirstWindowIsOver) {
  const Clock::time_point start{};
  UploadPace pace(kPace, kWindow, start);
  EXPECT_EQ(pace.bytes_per_window(), 5 * kPace);
  for (int second = 1; second < 5; ++second) {
    pace.record(start + std::chrono::seconds(second), static_cast<std::size_t>(second));
    EXPECT_FALSE(pace.too_slow(start + std::chrono::seconds(second))) << "the first window is free, second " << second;
  }
  EXPECT_EQ(pace.deadline(), start + kWindow);
  EXPECT_FALSE(pace.too_slow(start + kWindow - 1ms));
  EXPECT_TRUE(pace.too_slow(start + kWindow));
  pace.record(start + 6s, 6);
  EXPECT_TRUE(pace.too_slow(start + 6s)) << "a byte more does not buy time";
}

TEST(UploadPace, NothingAtAllIsTooSlowAfterTheFirstWindow) {
  const Clock::time_point start = Clock::now();
  UploadPace pace(kPace, kWindow, start);
  EXPECT_FALSE(pace.too_slow(start + 4s));
  EXPECT_TRUE(pace.too_slow(start + 5s));
}

TEST(UploadPace, ABodyThatKeepsThePaceIsNeverTooSlowHoweverLongItTakes) {
  const Clock::time_point start{};
  UploadPace pace(kPace, kWindow, start);
  // 20 KiB a second in pieces of 2 KiB, for four minutes (a 4.7 MiB body).
  std::size_t total = 0;
  for (auto at = start + 100ms; at < start + 240s; at += 100ms) {
    total += 2 * 1024;
    pace.record(at, total);
    ASSERT_FALSE(pace.too_slow(at)) << std::chrono::duration<double>(at - start).count() << " s";
    EXPECT_GT(pace.deadline(), at);
  }
}

TEST(UploadPace, ABodyThatStallsIsTooSlowAWindowAfterItsPaceFell) {
  const Clock::time_point start{};
  UploadPace pace(kPace, kWindow, start);
  // A megabyte in the first second, then nothing: the window that ends
  // five seconds after the last byte holds none of it.
  pace.record(start + 1s, 1024 * 1024);
  EXPECT_FALSE(pace.too_slow(start + 5s));
  EXPECT_EQ(pace.deadline(), start + 6s);
  EXPECT_TRUE(pace.too_slow(start + 6s));
}

TEST(UploadPace, ABodyThatSlowsBelowThePaceIsCaughtWithinAWindow) {
  const Clock::time_point start{};
  UploadPace pace(kPace, kWindow, start);
  std::size_t total = 0;
  auto at = start;
  for (; at < start + 10s; at += 1s) {  // twice the pace
    total += 2 * kPace;
    pace.record(at + 1s, total);
  }
  EXPECT_FALSE(pace.too_slow(at));
  bool caught = false;
  for (const auto slowed = at; at < slowed + 2 * kWindow; at += 1s) {  // half the pace
    total += kPace / 2;
    pace.record(at + 1s, total);
    if (pace.too_slow(at + 1s)) {
      caught = true;
      EXPECT_LE(at + 1s - slowed, kWindow) << "caught within a window of slowing";
      break;
    }
  }
  EXPECT_TRUE(caught);
}

TEST(UploadPace, NoPaceIsNeverTooSlow) {
  const Clock::time_point start{};
  UploadPace pace(0, kWindow, start);
  EXPECT_EQ(pace.deadline(), Clock::time_point::max());
  EXPECT_FALSE(pace.too_slow(start + 1h));
}

}  // namespace
}  // namespace fw::server
