#include "y4m_sink.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

// The writer itself is tested in tests/render; the sink's job is to say
// which flag to change.
TEST(Y4mSink, AnOddSizeNamesTheFlagsToChange) {
  std::string error;
  EXPECT_FALSE(Y4mSink::create("/dev/null", 5, 4, 15, error));
  EXPECT_EQ(error.rfind("--y4m ", 0), 0u) << error;
  EXPECT_NE(error.find("change --size"), std::string::npos) << error;
}

TEST(Y4mSink, PassesFramesToTheStream) {
  std::string error;
  auto sink = Y4mSink::create("/dev/null", 4, 2, 15, error);
  ASSERT_TRUE(sink) << error;
  EXPECT_TRUE(sink->write(model::RgbaImage(4, 2), error)) << error;
  EXPECT_FALSE(sink->write(model::RgbaImage(2, 2), error));
}

}  // namespace
}  // namespace fw::client
