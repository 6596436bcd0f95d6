#include "frame_writer.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "frame_reader.hpp"

namespace fw::codec {
namespace {

FrameDecision key_at(int level) {
  FrameDecision d;
  d.type = FrameType::key;
  d.level = level;
  return d;
}

TEST(FrameWriter, StartsWithVersionAndTypeThenTheSequenceNumberIfLossTolerant) {
  CodingState state(32);
  std::vector<std::uint8_t> out;
  write_frame(state, {}, 9, key_at(3), out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out[0], 0x21);
  CodingState lossy(32);
  std::vector<std::uint8_t> lossy_out;
  StreamOptions options;
  options.loss_tolerant = true;
  FrameDecision p;
  write_frame(lossy, options, 0, key_at(3), lossy_out);
  lossy_out.clear();
  write_frame(lossy, options, 201, p, lossy_out);
  ASSERT_GE(lossy_out.size(), 2u);
  EXPECT_EQ(lossy_out[0], 0x22);
  EXPECT_EQ(lossy_out[1], 201);
}

TEST(FrameWriter, ANothingChangedFrameTakesTwoBytesAtMost) {
  CodingState state(32);
  std::vector<std::uint8_t> out;
  write_frame(state, {}, 0, key_at(3), out);
  for (int i = 0; i < 20; ++i) {
    out.clear();
    FrameDecision nothing;
    nothing.level = 3;
    nothing.tick_delta = 15;
    write_frame(state, {}, 0, nothing, out);
    // Once the models have seen a few (seven group flags): the first byte and at most one more.
    if (i >= 5) {
      EXPECT_LE(out.size(), 2u) << "frame " << i;
    }
    EXPECT_LE(out.size(), 4u) << "frame " << i;
  }
}

TEST(FrameWriter, AppliesTheFrameToItsStateExactlyAsTheReaderDoes) {
  CodingState writer(32), reader(32);
  FrameDecision key = key_at(0);
  key.target[12] = 200;     // au9
  key.velocity[12] = -300;  // sub-steps per tick
  key.damping[12] = 3;
  key.target[29] = -500;    // head yaw
  key.target[35] = -480;    // left gaze: the eye at +20 steps in the head
  key.target[37] = -470;
  std::vector<std::uint8_t> out;
  write_frame(writer, {}, 0, key, out);
  std::uint32_t delta = 0;
  ASSERT_EQ(read_frame_payload(reader, FrameType::key, std::span(out).subspan(1), delta), DecodeError::ok);
  EXPECT_EQ(delta, 1u);
  EXPECT_EQ(writer.reconstruction.shown_all(), reader.reconstruction.shown_all());
  EXPECT_EQ(writer.reconstruction.shown(12), 200);
  EXPECT_EQ(writer.reconstruction.velocity(12), -320) << "rounded to quarter steps per tick";
  EXPECT_EQ(writer.reconstruction.damping(12), 3);
  const QuantisedParams fields = fields_from_coded(writer.reconstruction.shown_all());
  EXPECT_EQ(fields[35], 20);
  EXPECT_EQ(fields[37], 30);
}

TEST(FrameWriter, RoundsKeyValuesToTheLevelsUnits) {
  CodingState state(32);
  FrameDecision key = key_at(7);  // action units in units of 8 steps
  key.target[0] = 13;
  key.target[1] = 256;
  std::vector<std::uint8_t> out;
  write_frame(state, {}, 0, key, out);
  EXPECT_EQ(state.reconstruction.shown(0), 16);
  EXPECT_EQ(state.reconstruction.shown(1), 256);
}

}  // namespace
}  // namespace fw::codec
