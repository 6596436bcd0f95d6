#include <csetjmp>

#include <jpeglib.h>

#include "exif_orientation.hpp"
#include "photo_decoders.hpp"

namespace fw::photo {
namespace {

// libjpeg reports a fatal error through error_exit, which must not return:
// it jumps back to the setjmp below. Everything with a destructor that
// lives across the jump is made before the setjmp (C++ allows the jump then).
struct JpegErrors {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jump_back(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->jump, 1);
}

void stay_quiet(j_common_ptr, int) {}  // warnings (a short file, say) are not printed

// Adobe's CMYK JPEGs store the inks inverted; this is OpenCV's conversion, so
// that such a photo comes out as it did.
void cmyk_row_to_bgr(const std::uint8_t* cmyk, std::uint8_t* bgr, int width) {
  for (int x = 0; x < width; ++x, cmyk += 4, bgr += 3) {
    const int k = cmyk[3];
    bgr[2] = static_cast<std::uint8_t>(k - ((255 - cmyk[0]) * k >> 8));
    bgr[1] = static_cast<std::uint8_t>(k - ((255 - cmyk[1]) * k >> 8));
    bgr[0] = static_cast<std::uint8_t>(k - ((255 - cmyk[2]) * k >> 8));
  }
}

}  // namespace

std::optional<cv::Mat> decode_jpeg_photo(std::span<const std::uint8_t> bytes, PrepError& error) {
  jpeg_decompress_struct info{};
  JpegErrors errors{};
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = jump_back;
  errors.base.emit_message = stay_quiet;
  cv::Mat image, cmyk_row;
  int orientation = 1;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    error = {PrepErrorCode::undecodable,
             std::string("the image cannot be decoded (") + errors.message + "); the file may be damaged"};
    return std::nullopt;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_save_markers(&info, JPEG_APP0 + 1, 0xffff);
  jpeg_read_header(&info, TRUE);
  if (!decodable_size(info.image_width, info.image_height, error)) {
    jpeg_destroy_decompress(&info);
    return std::nullopt;
  }
  for (jpeg_saved_marker_ptr marker = info.marker_list; marker; marker = marker->next)
    if (marker->marker == JPEG_APP0 + 1 && orientation == 1)
      orientation = exif_orientation({marker->data, marker->data_length});
  const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_BGR;  // grey and YCbCr both come out as BGR
  jpeg_start_decompress(&info);
  image.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width), CV_8UC3);
  if (cmyk) cmyk_row.create(1, image.cols, CV_8UC4);
  while (info.output_scanline < info.output_height) {
    std::uint8_t* out = image.ptr(static_cast<int>(info.output_scanline));
    JSAMPROW rows[1] = {cmyk ? cmyk_row.ptr() : out};
    jpeg_read_scanlines(&info, rows, 1);
    if (cmyk) cmyk_row_to_bgr(cmyk_row.ptr(), out, image.cols);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  turn_upright(image, orientation);
  return image;
}

}  // namespace fw::photo
