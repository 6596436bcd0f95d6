#pragma once
// Room frames as numbered PNG files: DIR/frame_000001.png, ...
#include <filesystem>

#include "frame_sink.hpp"

namespace fw::client {

class PngSequenceSink : public FrameSink {
 public:
  /// Creates `directory` if needed.
  static std::unique_ptr<PngSequenceSink> create(const std::filesystem::path& directory, std::string& error);
  bool write(const model::RgbaImage& frame, std::string& error) override;

 private:
  explicit PngSequenceSink(std::filesystem::path directory) : directory_(std::move(directory)) {}
  std::filesystem::path directory_;
  int written_ = 0;
};

}  // namespace fw::client
