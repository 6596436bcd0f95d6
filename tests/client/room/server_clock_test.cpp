#include "server_clock.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(ServerClock, KnowsNothingBeforeAPong) {
  ServerClock clock;
  EXPECT_FALSE(clock.offset_us());
  EXPECT_FALSE(clock.elapsed_ms(1000, 2000));
}

TEST(ServerClock, PlacesTheServersStampHalfARoundTripAfterThePing) {
  ServerClock clock;
  // Ping left at 1000 us, pong back at 1400 us: the server stamped it at 1200 of ours.
  clock.pong({1, 1000, 501200}, 1400);
  EXPECT_EQ(clock.offset_us(), 500000);
  // A frame the server stamped at 600000 happened at 100000 of ours.
  EXPECT_DOUBLE_EQ(*clock.elapsed_ms(600000, 150000), 50.0);
  EXPECT_DOUBLE_EQ(*clock.elapsed_ms(600000, 90000), 0.0) << "never negative";
}

TEST(ServerClock, KeepsTheShortestRoundTrip) {
  ServerClock clock;
  clock.pong({1, 1000, 501200}, 1400);   // 400 us round trip
  clock.pong({2, 2000, 900000}, 4000);   // 2000 us: less trustworthy, ignored
  EXPECT_EQ(clock.offset_us(), 500000);
  clock.pong({3, 5000, 505100}, 5200);   // 200 us: better
  EXPECT_EQ(clock.offset_us(), 500000);
  clock.pong({4, 6000, 706050}, 6100);   // 100 us, and the server's clock moved on
  EXPECT_EQ(clock.offset_us(), 700000);
}

TEST(ServerClock, IgnoresPongsFromTheFutureAndForgetsOnReset) {
  ServerClock clock;
  clock.pong({1, 5000, 1}, 4000);
  EXPECT_FALSE(clock.offset_us());
  clock.pong({2, 1000, 2000}, 1000);
  EXPECT_TRUE(clock.offset_us());
  clock.reset();
  EXPECT_FALSE(clock.offset_us());
  clock.pong({3, 1000, 9000}, 3000);  // a slow round trip is fine after a reset
  EXPECT_EQ(clock.offset_us(), 9000 - 2000);
}

}  // namespace
}  // namespace fw::client
