#include "fw/codec/codec.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(StreamHeader, RoundTripsItsOptions) {
  for (const StreamOptions o : {StreamOptions{}, StreamOptions{true, 25, 0}, StreamOptions{false, 240, 255}}) {
    const auto bytes = write_stream_header(o);
    EXPECT_EQ(bytes[0], 0x20);
    EXPECT_EQ(std::string(bytes.begin() + 1, bytes.begin() + 5), "FWFP");
    EXPECT_EQ(bytes.size(), 11u + 11u * kChannelCount);
    StreamOptions back{true, 1, 1};
    ASSERT_EQ(read_stream_header(bytes, back), DecodeError::ok);
    EXPECT_EQ(back.loss_tolerant, o.loss_tolerant);
    EXPECT_EQ(back.tick_rate_hz, o.tick_rate_hz);
    EXPECT_EQ(back.max_extrapolation_ticks, o.max_extrapolation_ticks);
  }
}

TEST(StreamHeader, RefusesWhatItCannotDecodeAndSaysWhy) {
  const auto good = write_stream_header({});
  auto changed = [&](std::size_t i, std::uint8_t v) {
    auto b = good;
    b.at(i) = v;
    return b;
  };
  StreamOptions o;
  const StreamOptions untouched = o;
  EXPECT_EQ(read_stream_header({}, o), DecodeError::empty_frame);
  EXPECT_EQ(read_stream_header(changed(0, 0x10), o), DecodeError::unsupported_version) << "version 1";
  EXPECT_EQ(read_stream_header(changed(0, 0x30), o), DecodeError::unsupported_version);
  EXPECT_EQ(read_stream_header(changed(0, 0x21), o), DecodeError::wrong_frame_type);
  EXPECT_EQ(read_stream_header(changed(0, 0x2A), o), DecodeError::unknown_frame_type);
  EXPECT_EQ(read_stream_header(changed(2, 'w'), o), DecodeError::bad_magic);
  EXPECT_EQ(read_stream_header(changed(5, 1), o), DecodeError::unsupported_schema) << "schema 1: no correctives";
  EXPECT_EQ(read_stream_header(changed(5, 3), o), DecodeError::unsupported_schema);
  EXPECT_EQ(read_stream_header(changed(7, 0x80), o), DecodeError::bad_stream_options);
  EXPECT_EQ(read_stream_header(changed(8, 0), o), DecodeError::bad_stream_options);
  EXPECT_EQ(read_stream_header(changed(10, 48), o), DecodeError::channel_table_mismatch);
  // Each field of a channel entry: group, min, max, step, partner, base.
  for (std::size_t field : {0u, 1u, 3u, 5u, 9u, 10u})
    EXPECT_EQ(read_stream_header(changed(11 + 11 * 37 + field, good[11 + 11 * 37 + field] ^ 0x04), o),
              DecodeError::channel_table_mismatch)
        << field;
  // A corrective channel's entry (the last six): step, range, group.
  const std::size_t corrective = 11 + 11 * (kChannelCount - 1);
  for (std::size_t field : {0u, 1u, 3u, 5u, 9u, 10u})
    EXPECT_EQ(read_stream_header(changed(corrective + field, good[corrective + field] ^ 0x04), o),
              DecodeError::channel_table_mismatch)
        << "corrective entry, field " << field;
  // A header of the 47 channels of schema 1 under this version's number.
  auto schema1_table = good;
  schema1_table[10] = 47;
  schema1_table.resize(11 + 11 * 47);
  EXPECT_EQ(read_stream_header(schema1_table, o), DecodeError::channel_table_mismatch);
  for (std::size_t n = 1; n < good.size(); ++n)
    EXPECT_EQ(read_stream_header(std::span(good).first(n), o), DecodeError::truncated) << n;
  auto longer = good;
  longer.push_back(0);
  EXPECT_EQ(read_stream_header(longer, o), DecodeError::trailing_bytes);
  EXPECT_EQ(o.tick_rate_hz, untouched.tick_rate_hz) << "options only change on success";
}

}  // namespace
}  // namespace fw::codec
