#include "fw/render/jpeg_codec.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>

#include <jpeglib.h>

namespace fw::render {
namespace {

// libjpeg reports fatal errors through error_exit, which must not return:
// it jumps back to the setjmp in the calling function. Only trivially
// destructible objects live between setjmp and the jump (C++ allows longjmp
// then), so everything with a destructor is created before setjmp.
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
  auto* manager = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, manager->message);
  std::longjmp(manager->jump, 1);
}

void ignore_message(j_common_ptr, int) {}  // warnings (e.g. a short file) are not printed to stderr

}  // namespace

bool is_jpeg(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

bool decode_jpeg(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error) {
  if (!is_jpeg(bytes)) {
    error = "not a JPEG image";
    return false;
  }
  jpeg_decompress_struct info{};
  ErrorManager errors{};
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = on_error;
  errors.base.emit_message = ignore_message;
  model::RgbaImage decoded;
  std::vector<std::uint8_t> row;
  bool too_large = false;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    error = std::string("damaged JPEG image: ") + errors.message;
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  const int width = static_cast<int>(info.image_width), height = static_cast<int>(info.image_height);
  if (width <= 0 || height <= 0 || width > max_side || height > max_side) {
    too_large = true;
  } else {
    info.out_color_space = JCS_RGB;  // grey and YCbCr both come out as RGB
    jpeg_start_decompress(&info);
    decoded = model::RgbaImage(width, height);
    row.resize(static_cast<std::size_t>(width) * 3);
    while (info.output_scanline < info.output_height) {
      const int y = static_cast<int>(info.output_scanline);
      JSAMPROW rows[1] = {row.data()};
      jpeg_read_scanlines(&info, rows, 1);
      std::uint8_t* out = decoded.at(0, y);
      for (int x = 0; x < width; ++x) {
        out[4 * x + 0] = row[3 * x + 0];
        out[4 * x + 1] = row[3 * x + 1];
        out[4 * x + 2] = row[3 * x + 2];
        out[4 * x + 3] = 255;
      }
    }
    jpeg_finish_decompress(&info);
  }
  jpeg_destroy_decompress(&info);
  if (too_large) {
    error = "JPEG image of " + std::to_string(width) + "x" + std::to_string(height) + " pixels; at most " +
            std::to_string(max_side) + " on a side is accepted";
    return false;
  }
  image = std::move(decoded);
  return true;
}

bool encode_jpeg(const model::RgbaImage& image, int quality, std::vector<std::uint8_t>& bytes, std::string& error) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    error = "cannot encode an empty image as JPEG";
    return false;
  }
  jpeg_compress_struct info{};
  ErrorManager errors{};
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = on_error;
  errors.base.emit_message = ignore_message;
  std::vector<std::uint8_t> row(static_cast<std::size_t>(image.width) * 3);
  unsigned char* buffer = nullptr;  // malloc'ed by jpeg_mem_dest, freed below
  unsigned long size = 0;
  if (setjmp(errors.jump)) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    error = std::string("JPEG encoding failed: ") + errors.message;
    return false;
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(image.width);
  info.image_height = static_cast<JDIMENSION>(image.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality < 1 ? 1 : quality > 100 ? 100 : quality, TRUE);
  info.optimize_coding = TRUE;  // a few per cent smaller, for the slow upload
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    const std::uint8_t* in = image.at(0, static_cast<int>(info.next_scanline));
    for (int x = 0; x < image.width; ++x) {
      row[3 * x + 0] = in[4 * x + 0];
      row[3 * x + 1] = in[4 * x + 1];
      row[3 * x + 2] = in[4 * x + 2];
    }
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  bytes.assign(buffer, buffer + size);
  std::free(buffer);
  return true;
}

}  // namespace fw::render
