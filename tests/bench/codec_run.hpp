#pragma once
// Runs one scene through the codec as the server and a client would: one
// encoder per avatar at a per-avatar budget, one room frame per tick with the
// frames that went out, a RoomDecoder on the other side; measures the bits
// (every byte of the room frame attributed to an avatar) and the difference
// between what the viewer sees and the original parameters.
#include <cstdint>
#include <vector>

#include "fw/codec/codec.hpp"
#include "fw/behavior/scene_file.hpp"

namespace fw::bench {

// Scene files moved to avatar/behavior, which records them.
using behavior::read_scene;
using behavior::Scene;
using behavior::SceneAvatar;
using behavior::write_scene;

struct CodecRunOptions {
  double target_bps_per_avatar = 500;
  bool loss_tolerant = false;
  int min_level = codec::EncoderOptions{}.min_level;
  int max_level = codec::EncoderOptions{}.max_level;
  /// The encoder's refresh interval in ticks (0: none; the room server uses 2).
  int refresh_ticks = 0;
  /// Keep what the viewer sees of this avatar at every tick (for the video
  /// comparison); -1 keeps nothing.
  int record_avatar = -1;
};

struct AvatarRun {
  bool idle = false;
  std::vector<double> bits_per_tick;  ///< room-frame bits attributed to this avatar, per tick
  std::uint64_t frames = 0, key_frames = 0, frame_bytes = 0;
};

struct CodecRun {
  std::vector<AvatarRun> avatars;
  double gaze_max_deg = 0;         ///< eye direction in the world (head and eye rotations), worst eye and tick
  double eye_in_head_max_deg = 0;  ///< eye direction relative to the head
  double au_max_error = 0;         ///< intensity units (0..1)
  double au_rms_error = 0;
  double head_rotation_max_deg = 0;  ///< worst of yaw, pitch, roll
  double head_translation_max_mm = 0;
  double lid_max_error = 0;
  double colour_max_error = 0;
  double corrective_max_error = 0;  ///< largest error of a corrective weight
  double corrective_rms_error = 0;
  double vertex_rms_mm = 0;        ///< skin vertices, posed, face at 63 mm inter-ocular distance
  double vertex_max_mm = 0;
  std::vector<codec::FaceParams> recorded;  ///< options.record_avatar's shown face per tick
  std::uint64_t decode_errors = 0;  ///< must stay 0: the room decoder disagreed or refused a frame
  std::uint64_t room_frames = 0;
  std::uint64_t room_bytes = 0;
  int fps = 30;
};

/// `p` clamped to the ranges the format carries: distortion is measured
/// against what an exact codec could show.
codec::FaceParams in_range(const codec::FaceParams& p);

CodecRun run_codec(const Scene& scene, const CodecRunOptions& options);

}  // namespace fw::bench
