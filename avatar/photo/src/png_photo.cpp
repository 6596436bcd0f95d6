#include <csetjmp>
#include <cstring>
#include <string>

#include <png.h>

#include "photo_decoders.hpp"

namespace fw::photo {
namespace {

// The PNG read from memory, a chunk at a time as libpng asks for it.
struct MemoryInput {
  std::span<const std::uint8_t> bytes;
  std::size_t at = 0;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t length) {
  auto* input = static_cast<MemoryInput*>(png_get_io_ptr(png));
  if (length > input->bytes.size() - input->at) png_error(png, "the file ends before the image does");
  std::memcpy(out, input->bytes.data() + input->at, length);
  input->at += length;
}

void stay_quiet(png_structp, png_const_charp) {}  // warnings are not printed

// A fatal error: its text is kept for the person (libpng's default would
// print it to the server's stderr), then libpng's jump to the setjmp below.
[[noreturn]] void keep_and_jump(png_structp png, png_const_charp message) {
  auto* kept = static_cast<std::string*>(png_get_error_ptr(png));
  if (kept->empty()) *kept = message;
  png_longjmp(png, 1);
}

}  // namespace

std::optional<cv::Mat> decode_png_photo(std::span<const std::uint8_t> bytes, PrepError& error) {
  // libpng reports a fatal error by longjmp to the setjmp below: everything
  // with a destructor is made before it.
  std::string failure;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure, keep_and_jump, stay_quiet);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    error = {PrepErrorCode::undecodable, "the image cannot be decoded (out of memory)"};
    return std::nullopt;
  }
  MemoryInput input{bytes};
  cv::Mat image;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    error = {PrepErrorCode::undecodable, "the image cannot be decoded (" + failure + "); the file may be damaged"};
    return std::nullopt;
  }
  png_set_read_fn(png, &input, read_from_memory);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
  if (!decodable_size(width, height, error)) {
    png_destroy_read_struct(&png, &info, nullptr);
    return std::nullopt;
  }
  // Whatever the PNG holds comes out as 8-bit BGR: 16-bit samples keep their
  // high byte, palettes and grey expand, alpha (and tRNS) is dropped, as
  // OpenCV's IMREAD_COLOR did; no gamma is applied.
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_palette_to_rgb(png);
  png_set_expand_gray_1_2_4_to_8(png);
  png_set_gray_to_rgb(png);
  png_set_bgr(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != static_cast<png_size_t>(width) * 3)
    png_error(png, "unexpected sample layout");
  image.create(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
  rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.ptr(static_cast<int>(y));
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

}  // namespace fw::photo
