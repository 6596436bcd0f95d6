#pragma once
// Where a frame's time goes, part by part (clear, skin, eyes, mouth, shell,
// resolve, read-back) and shader variant by shader variant, for
// `facewire-bench render --profile`. llvmpipe has no GL timer queries, so
// the renderer waits for each part to finish (glFinish) and reads the
// clock: a profiled frame is slower than a normal one (every part is its
// own pass over the target's tiles), so the shares count, not the sum.
// Not thread-safe: one renderer fills it.
#include <map>
#include <string>
#include <string_view>

namespace fw::render {

struct FrameProfile {
  std::map<std::string, double, std::less<>> part_seconds;     ///< by part name
  std::map<std::string, double, std::less<>> variant_seconds;  ///< by shader variant name
  int frames = 0;                                              ///< frames rendered while profiling

  /// Adds `seconds` (>= 0) to `part` and, unless `variant` is empty, to `variant`.
  void add(std::string_view part, std::string_view variant, double seconds);
  /// Milliseconds per frame of each part (each variant with `variants`); empty before the first frame.
  std::map<std::string, double, std::less<>> per_frame_ms(bool variants) const;
};

}  // namespace fw::render
