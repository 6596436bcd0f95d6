#include "png_sequence_sink.hpp"

#include <cstdio>

#include "fw/render/png.hpp"

namespace fw::client {

std::unique_ptr<PngSequenceSink> PngSequenceSink::create(const std::filesystem::path& directory, std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory)) {
    error = "--out " + directory.string() + ": cannot create the directory (" + ec.message() + ")";
    return nullptr;
  }
  return std::unique_ptr<PngSequenceSink>(new PngSequenceSink(directory));
}

bool PngSequenceSink::write(const model::RgbaImage& frame, std::string& error) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06d.png", ++written_);
  return render::write_png(frame, directory_ / name, error);
}

}  // namespace fw::client
