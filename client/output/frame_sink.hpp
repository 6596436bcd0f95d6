#pragma once
// Where rendered room frames go: PNG files in a directory, a Y4M video
// stream, a window. One interface so the join loop writes to any of them.
#include <memory>
#include <string>

#include "fw/model/image.hpp"

namespace fw::client {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// Takes one frame (all frames of one sink have the same size).
  /// @return false and `error` when the sink cannot take more (disk full,
  ///         the player closed the pipe, the window was closed)
  virtual bool write(const model::RgbaImage& frame, std::string& error) = 0;
};

}  // namespace fw::client
