// The stream header message (FORMAT.md, "Stream header").
#include <cstring>

#include "frame_writer.hpp"
#include "fw/codec/byte_reader.hpp"
#include "fw/codec/byte_writer.hpp"

namespace fw::codec {
namespace {

constexpr std::uint8_t kMagic[4] = {'F', 'W', 'F', 'P'};
constexpr std::uint8_t kFlagLossTolerant = 0x01;

}  // namespace

std::vector<std::uint8_t> write_stream_header(const StreamOptions& options) {
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.u8(first_byte(FrameType::stream_header));
  w.bytes(kMagic);
  w.u16_le(kFaceParamsSchema);
  w.u8(options.loss_tolerant ? kFlagLossTolerant : 0);
  w.u8(options.tick_rate_hz);
  w.u8(options.max_extrapolation_ticks);
  w.u8(static_cast<std::uint8_t>(kChannelCount));
  for (const ChannelInfo& info : channel_table()) {
    w.u8(static_cast<std::uint8_t>(info.group));
    w.i16_le(static_cast<std::int16_t>(info.min_q));
    w.i16_le(static_cast<std::int16_t>(info.max_q));
    w.f32_le(info.step);
    w.u8(static_cast<std::uint8_t>(info.partner));
    w.u8(static_cast<std::uint8_t>(info.base));
  }
  return out;
}

DecodeError read_stream_header(std::span<const std::uint8_t> bytes, StreamOptions& options) {
  if (bytes.empty()) return DecodeError::empty_frame;
  ByteReader r(bytes);
  const std::uint8_t first = r.u8();
  if ((first >> 4) != kFormatVersion) return DecodeError::unsupported_version;
  if ((first & 0x0F) > static_cast<std::uint8_t>(FrameType::resync_request)) return DecodeError::unknown_frame_type;
  if ((first & 0x0F) != static_cast<std::uint8_t>(FrameType::stream_header)) return DecodeError::wrong_frame_type;
  const auto magic = r.bytes(4);
  if (r.failed()) return DecodeError::truncated;
  if (std::memcmp(magic.data(), kMagic, 4) != 0) return DecodeError::bad_magic;
  const std::uint16_t schema = r.u16_le();
  const std::uint8_t flags = r.u8();
  StreamOptions parsed;
  parsed.tick_rate_hz = r.u8();
  parsed.max_extrapolation_ticks = r.u8();
  const std::uint8_t channels = r.u8();
  if (r.failed()) return DecodeError::truncated;
  if (schema != kFaceParamsSchema) return DecodeError::unsupported_schema;
  if ((flags & ~kFlagLossTolerant) != 0 || parsed.tick_rate_hz == 0) return DecodeError::bad_stream_options;
  parsed.loss_tolerant = (flags & kFlagLossTolerant) != 0;
  if (channels != kChannelCount) return DecodeError::channel_table_mismatch;
  for (const ChannelInfo& info : channel_table()) {
    const std::uint8_t group = r.u8();
    const std::int16_t min_q = r.i16_le();
    const std::int16_t max_q = r.i16_le();
    const float step = r.f32_le();
    const auto partner = static_cast<std::int8_t>(r.u8());
    const auto base = static_cast<std::int8_t>(r.u8());
    if (r.failed()) return DecodeError::truncated;
    // Bit-exact step comparison: the table is copied, never computed.
    std::uint32_t step_bits = 0, expected_bits = 0;
    std::memcpy(&step_bits, &step, 4);
    std::memcpy(&expected_bits, &info.step, 4);
    if (group != static_cast<std::uint8_t>(info.group) || min_q != info.min_q || max_q != info.max_q ||
        step_bits != expected_bits || partner != info.partner || base != info.base) {
      return DecodeError::channel_table_mismatch;
    }
  }
  if (r.remaining() != 0) return DecodeError::trailing_bytes;
  options = parsed;
  return DecodeError::ok;
}

}  // namespace fw::codec
