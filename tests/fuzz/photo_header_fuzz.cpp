// Fuzzes the first look at an uploaded photo (avatar/photo's inspect_photo,
// which AvatarPreparer::check_photo and prepare() run before anything is
// decoded): format by signature, byte and pixel limits from the header,
// and that the file is complete. Whatever the bytes: no crash and no read
// outside the file, a reason whenever the photo is refused, and a header
// that is accepted names its own format and a size within the limits.
// Since this check is what keeps a decompression bomb (a small file that
// says it is huge) from the decoders, the size it accepts must be the size
// the decoders themselves will read from the same bytes: libpng, libjpeg
// and libwebp, the libraries OpenCV decodes with, are asked for the header
// too, and where they read one it must agree. Seeded with small photos of
// each format (corpus/photo_header_fuzz, written by fuzz_make_seeds).
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <span>

#include <jpeglib.h>
#include <png.h>
#include <webp/decode.h>

#include "fw/photo/photo_limits.hpp"
#include "image_inspection.hpp"
#include "seed_check.hpp"

namespace {

using Bytes = std::span<const std::uint8_t>;

struct Size {
  long width = 0, height = 0;
};

std::optional<Size> png_size(Bytes bytes) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    png_image_free(&png);
    return std::nullopt;
  }
  const Size size{static_cast<long>(png.width), static_cast<long>(png.height)};
  png_image_free(&png);
  return size;
}

struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
};

std::optional<Size> jpeg_size(Bytes bytes) {
  jpeg_decompress_struct jpeg{};
  JpegErrors errors{};
  jpeg.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = [](j_common_ptr j) { std::longjmp(reinterpret_cast<JpegErrors*>(j->err)->jump, 1); };
  errors.manager.output_message = [](j_common_ptr) {};
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&jpeg);
    return std::nullopt;
  }
  jpeg_create_decompress(&jpeg);
  jpeg_mem_src(&jpeg, const_cast<unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  std::optional<Size> size;
  if (jpeg_read_header(&jpeg, TRUE) == JPEG_HEADER_OK)
    size = Size{static_cast<long>(jpeg.image_width), static_cast<long>(jpeg.image_height)};
  jpeg_destroy_decompress(&jpeg);
  return size;
}

std::optional<Size> webp_size(Bytes bytes) {
  WebPBitstreamFeatures features{};
  if (WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK) return std::nullopt;
  return Size{features.width, features.height};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fw::photo;
  const Bytes bytes(data, size);
  PrepError error;
  const std::optional<PhotoHeader> header = inspect_photo(bytes, error);
  if (!header) {
    if (error.message.empty()) std::abort();
    fw::fuzz::seed_refused(error.message);
    return 0;
  }
  if (header->width <= 0 || header->height <= 0 ||
      static_cast<std::uint64_t>(header->width) * static_cast<std::uint64_t>(header->height) > kMaxPhotoPixels)
    std::abort();
  std::optional<Size> decoders;
  switch (header->format) {
    case PhotoFormat::png:
      if (size < 8 || std::memcmp(data, "\x89PNG", 4) != 0) std::abort();
      decoders = png_size(bytes);
      break;
    case PhotoFormat::jpeg:
      if (size < 3 || data[0] != 0xFF || data[1] != 0xD8) std::abort();
      decoders = jpeg_size(bytes);
      break;
    case PhotoFormat::webp:
      if (size < 12 || std::memcmp(data, "RIFF", 4) != 0 || std::memcmp(data + 8, "WEBP", 4) != 0) std::abort();
      decoders = webp_size(bytes);
      break;
  }
  if (decoders && (decoders->width != header->width || decoders->height != header->height)) {
    std::fprintf(stderr, "the header check read %dx%d, the decoder's library reads %ldx%ld\n", header->width,
                 header->height, decoders->width, decoders->height);
    std::abort();
  }
  return 0;
}
