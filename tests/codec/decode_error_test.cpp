#include "fw/codec/codec.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

// The numbers are part of the format (FORMAT.md, "Error codes"): a change
// here breaks every decoder in the field. Add new codes at the end.
TEST(DecodeError, NumbersNeverChange) {
  EXPECT_EQ(static_cast<int>(DecodeError::ok), 0);
  EXPECT_EQ(static_cast<int>(DecodeError::empty_frame), 1);
  EXPECT_EQ(static_cast<int>(DecodeError::unsupported_version), 2);
  EXPECT_EQ(static_cast<int>(DecodeError::unknown_frame_type), 3);
  EXPECT_EQ(static_cast<int>(DecodeError::wrong_frame_type), 4);
  EXPECT_EQ(static_cast<int>(DecodeError::bad_magic), 5);
  EXPECT_EQ(static_cast<int>(DecodeError::unsupported_schema), 6);
  EXPECT_EQ(static_cast<int>(DecodeError::channel_table_mismatch), 7);
  EXPECT_EQ(static_cast<int>(DecodeError::bad_stream_options), 8);
  EXPECT_EQ(static_cast<int>(DecodeError::truncated), 9);
  EXPECT_EQ(static_cast<int>(DecodeError::awaiting_key_frame), 10);
  EXPECT_EQ(static_cast<int>(DecodeError::sequence_gap), 11);
  EXPECT_EQ(static_cast<int>(DecodeError::stale_frame), 12);
  EXPECT_EQ(static_cast<int>(DecodeError::value_out_of_range), 13);
  EXPECT_EQ(static_cast<int>(DecodeError::check_failed), 14);
  EXPECT_EQ(static_cast<int>(DecodeError::too_many_avatars), 15);
  EXPECT_EQ(static_cast<int>(DecodeError::duplicate_avatar), 16);
  EXPECT_EQ(static_cast<int>(DecodeError::frame_too_large), 17);
  EXPECT_EQ(static_cast<int>(DecodeError::trailing_bytes), 18);
  EXPECT_EQ(static_cast<int>(FrameType::stream_header), 0);
  EXPECT_EQ(static_cast<int>(FrameType::key), 1);
  EXPECT_EQ(static_cast<int>(FrameType::predicted), 2);
  EXPECT_EQ(static_cast<int>(FrameType::room), 3);
  EXPECT_EQ(static_cast<int>(FrameType::resync_request), 4);
}

TEST(DecodeError, EveryCodeHasItsOwnSentence) {
  std::set<std::string> sentences;
  for (int i = 0; i <= 18; ++i) {
    const std::string s(describe(static_cast<DecodeError>(i)));
    EXPECT_GT(s.size(), 5u) << i;
    sentences.insert(s);
  }
  EXPECT_EQ(sentences.size(), 19u);
  EXPECT_EQ(describe(static_cast<DecodeError>(200)), "unknown error code");
}

}  // namespace
}  // namespace fw::codec
