#include "codec_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "fw/codec/codec.hpp"
#include "fw/model/avatar_model.hpp"
#include "vertex_error.hpp"

namespace fw::bench {
namespace {

using Vec3 = std::array<double, 3>;

// Direction of an eye in the head frame (z toward the viewer, x toward the
// person's left, y up): yaw turns toward +x, pitch toward +y.
Vec3 eye_direction(double yaw, double pitch) {
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

// The head rotation of FaceParams: roll, then pitch, then yaw.
Vec3 rotate_head(const Vec3& v, double yaw, double pitch, double roll) {
  const Vec3 r{std::cos(roll) * v[0] + std::sin(roll) * v[1], -std::sin(roll) * v[0] + std::cos(roll) * v[1], v[2]};
  const Vec3 p{r[0], std::cos(pitch) * r[1] + std::sin(pitch) * r[2], -std::sin(pitch) * r[1] + std::cos(pitch) * r[2]};
  return {std::cos(yaw) * p[0] + std::sin(yaw) * p[2], p[1], -std::sin(yaw) * p[0] + std::cos(yaw) * p[2]};
}

double angle_deg(const Vec3& a, const Vec3& b) {
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const Vec3 cross{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]), dot) * 180.0 /
         std::numbers::pi;
}

struct Distortion {
  double gaze = 0, eye = 0, au = 0, au_sq = 0, head_rot = 0, head_mm = 0, lid = 0, colour = 0, corrective = 0, corrective_sq = 0;
  std::uint64_t au_samples = 0, corrective_samples = 0;

  void add(const codec::FaceParams& o, const codec::FaceParams& d) {
    const std::pair<const codec::EyeRotation*, const codec::EyeRotation*> eyes[] = {{&o.eye_left, &d.eye_left},
                                                                                    {&o.eye_right, &d.eye_right}};
    for (const auto& [oe, de] : eyes) {
      const Vec3 oh = eye_direction(oe->yaw_rad, oe->pitch_rad), dh = eye_direction(de->yaw_rad, de->pitch_rad);
      eye = std::max(eye, angle_deg(oh, dh));
      gaze = std::max(gaze, angle_deg(rotate_head(oh, o.head_yaw_rad, o.head_pitch_rad, o.head_roll_rad),
                                      rotate_head(dh, d.head_yaw_rad, d.head_pitch_rad, d.head_roll_rad)));
    }
    for (std::size_t i = 0; i < o.au.size(); ++i) {
      const double e = std::abs(static_cast<double>(o.au[i]) - d.au[i]);
      au = std::max(au, e);
      au_sq += e * e;
      ++au_samples;
    }
    for (const auto& [a, b] : {std::pair{o.head_yaw_rad, d.head_yaw_rad}, std::pair{o.head_pitch_rad, d.head_pitch_rad},
                              std::pair{o.head_roll_rad, d.head_roll_rad}})
      head_rot = std::max(head_rot, std::abs(static_cast<double>(a) - b) * 180.0 / std::numbers::pi);
    for (std::size_t i = 0; i < 3; ++i)
      head_mm = std::max(head_mm, std::abs(static_cast<double>(o.head_translation_mm[i]) - d.head_translation_mm[i]));
    lid = std::max({lid, std::abs(static_cast<double>(o.lid_left) - d.lid_left),
                    std::abs(static_cast<double>(o.lid_right) - d.lid_right)});
    for (std::size_t i = 0; i < o.blush.size(); ++i)
      colour = std::max(colour, std::abs(static_cast<double>(o.blush[i]) - d.blush[i]));
    colour = std::max(colour, std::abs(static_cast<double>(o.pallor) - d.pallor));
    for (std::size_t i = 0; i < o.corrective.size(); ++i)
    {
      const double e = std::abs(static_cast<double>(o.corrective[i]) - d.corrective[i]);
      corrective = std::max(corrective, e);
      corrective_sq += e * e;
      ++corrective_samples;
    }
  }
};

}  // namespace

// The parameters clamped to the ranges the format carries: distortion is
// measured against what an exact codec could show, not against out-of-range
// inputs (the synthetic scene stays in range anyway).
codec::FaceParams in_range(const codec::FaceParams& p) {
  codec::FaceParams q = p;
  const auto& table = codec::channel_table();
  for (std::size_t c = 0; c < codec::kChannelCount; ++c) {
    const float lo = static_cast<float>(table[c].min_q) * table[c].step;
    const float hi = static_cast<float>(table[c].max_q) * table[c].step;
    codec::set_channel_value(q, c, std::clamp(codec::channel_value(p, c), lo, hi));
  }
  return q;
}

CodecRun run_codec(const Scene& scene, const CodecRunOptions& options) {
  CodecRun run;
  run.fps = scene.fps;
  const std::size_t n = scene.avatars.size();
  codec::EncoderOptions encoder_options;
  encoder_options.stream.loss_tolerant = options.loss_tolerant;
  encoder_options.stream.tick_rate_hz = static_cast<std::uint8_t>(std::clamp(scene.fps, 1, 240));
  if (options.loss_tolerant) encoder_options.stream.max_extrapolation_ticks = 15;
  encoder_options.target_bps = options.target_bps_per_avatar;
  encoder_options.min_level = options.min_level;
  encoder_options.max_level = options.max_level;
  encoder_options.refresh_ticks = options.refresh_ticks;
  encoder_options.container_bytes_per_frame = 2;  // the room frame entry, about
  std::vector<codec::Encoder> encoders;
  for (std::size_t a = 0; a < n; ++a) encoders.emplace_back(encoder_options);
  codec::RoomDecoder room_decoder(encoder_options.stream);
  std::vector<std::uint32_t> ticks_since_frame(n, 0);
  run.avatars.resize(n);
  for (std::size_t a = 0; a < n; ++a) run.avatars[a].idle = scene.avatars[a].idle;

  Distortion distortion;
  static const model::AvatarModel generic = model::generic_avatar_model();
  VertexError vertex_error(generic);
  std::vector<std::vector<std::uint8_t>> frames(n);
  std::vector<codec::RoomEntry> entries;
  std::vector<std::size_t> entry_avatar;
  std::vector<std::uint8_t> room;
  for (std::size_t t = 0; t < scene.tick_count(); ++t) {
    entries.clear();
    entry_avatar.clear();
    for (std::size_t a = 0; a < n; ++a) {
      run.avatars[a].bits_per_tick.push_back(0.0);
      if (encoders[a].encode(scene.avatars[a].ticks[t], frames[a])) {
        entries.push_back({static_cast<std::uint32_t>(a), frames[a]});
        entry_avatar.push_back(a);
        ++run.avatars[a].frames;
        run.avatars[a].frame_bytes += frames[a].size();
        if (encoders[a].stats().last_type == codec::FrameType::key) ++run.avatars[a].key_frames;
      }
    }
    if (!entries.empty()) {
      room.clear();
      codec::write_room_frame(entries, room);
      ++run.room_frames;
      run.room_bytes += room.size();
      // Each entry's own bytes go to its avatar; the room frame's first
      // byte and count are shared.
      std::size_t entry_total = 0;
      std::vector<std::size_t> entry_bytes(entries.size());
      for (std::size_t i = 0; i < entries.size(); ++i) {
        const bool more = i + 1 < entries.size();
        entry_bytes[i] = entries[i].frame.size() + (entries[i].avatar_id < 64 ? 1 : 2);
        if (more) entry_bytes[i] += entries[i].frame.size() < 128 ? 1 : 2;
        entry_total += entry_bytes[i];
      }
      const double shared = static_cast<double>(room.size() - entry_total) / static_cast<double>(entries.size());
      for (std::size_t i = 0; i < entries.size(); ++i)
        run.avatars[entry_avatar[i]].bits_per_tick.back() = 8.0 * (static_cast<double>(entry_bytes[i]) + shared);
      const auto result = room_decoder.decode(room);
      if (result.error != codec::DecodeError::ok) ++run.decode_errors;
      for (const auto& [id, error] : result.avatars)
        if (error != codec::DecodeError::ok) ++run.decode_errors;
    }
    for (std::size_t a = 0; a < n; ++a) {
      if (!entries.empty() &&
          std::find(entry_avatar.begin(), entry_avatar.end(), a) != entry_avatar.end()) {
        ticks_since_frame[a] = 0;
      } else {
        ++ticks_since_frame[a];
      }
      const codec::Decoder* decoder = room_decoder.avatar(static_cast<std::uint32_t>(a));
      const codec::QuantisedParams shown = decoder ? decoder->quantised(ticks_since_frame[a]) : codec::QuantisedParams{};
      if (shown != encoders[a].reconstruction()) ++run.decode_errors;
      const codec::FaceParams original = in_range(scene.avatars[a].ticks[t]);
      const codec::FaceParams seen = codec::dequantise(shown);
      distortion.add(original, seen);
      vertex_error.add(original, seen);
      if (static_cast<int>(a) == options.record_avatar) run.recorded.push_back(seen);
    }
  }
  run.gaze_max_deg = distortion.gaze;
  run.eye_in_head_max_deg = distortion.eye;
  run.au_max_error = distortion.au;
  run.au_rms_error = distortion.au_samples ? std::sqrt(distortion.au_sq / static_cast<double>(distortion.au_samples)) : 0;
  run.head_rotation_max_deg = distortion.head_rot;
  run.head_translation_max_mm = distortion.head_mm;
  run.lid_max_error = distortion.lid;
  run.colour_max_error = distortion.colour;
  run.corrective_max_error = distortion.corrective;
  run.corrective_rms_error = distortion.corrective_samples
                                 ? std::sqrt(distortion.corrective_sq / static_cast<double>(distortion.corrective_samples))
                                 : 0.0;
  run.vertex_rms_mm = vertex_error.rms_mm();
  run.vertex_max_mm = vertex_error.max_mm();
  return run;
}

}  // namespace fw::bench
