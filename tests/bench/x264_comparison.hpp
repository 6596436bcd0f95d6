#pragma once
// What a video codec would need for the same face: one avatar's track of a
// scene rendered by our renderer (the astronaut's avatar, 256x256, 30 fps)
// from the original parameters is the reference; the same track rendered
// from what our decoder shows gives our picture quality (PSNR); x264 (through
// ffmpeg) then codes the reference at the highest CRF that still reaches that
// PSNR, and its bit rate is set against ours.
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::bench {

struct X264Comparison {
  std::string skipped;       ///< why the comparison did not run (empty when it did)
  int frames = 0;
  double ours_psnr_db = 0;   ///< decoded parameters' render against the reference render
  double ours_bps = 0;
  double x264_crf = 0;       ///< the coarsest CRF whose PSNR is at least ours
  double x264_psnr_db = 0;
  double x264_bps = 0;       ///< raw H.264 stream, no container
  bool x264_reached = false;  ///< whether any CRF reached our PSNR (else: its best)
  std::string x264_settings;
};

/// `original` and `shown`: one avatar's faces per tick (the same length).
/// `photo`: the portrait the avatar is prepared from.
X264Comparison compare_with_x264(const std::vector<codec::FaceParams>& original,
                                 const std::vector<codec::FaceParams>& shown, double ours_bps, int fps,
                                 const std::string& photo);

}  // namespace fw::bench
