#include "fw/photo/photo_limits.hpp"

#include <cstdlib>
#include <string>

#include <unistd.h>

namespace fw::photo {

void enforce_decoder_pixel_limit(char** argv) {
  const std::string limit = std::to_string(kMaxPhotoPixels);
  const char* current = std::getenv("OPENCV_IO_MAX_IMAGE_PIXELS");
  if (current && limit == current) return;
  if (::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", limit.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);  // returns only on failure
}

}  // namespace fw::photo
