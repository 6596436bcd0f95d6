#pragma once
// What can go wrong turning a photo into an avatar. Each error carries a
// message for a person: what was wrong and what to do.
#include <string>

namespace fw::photo {

enum class PrepErrorCode {
  not_an_image,        ///< no known image signature
  unsupported_format,  ///< an image, but not JPEG, PNG or WebP (or an animated WebP)
  too_many_bytes,
  too_many_pixels,
  truncated,           ///< the file ends before the image does
  undecodable,         ///< the decoder refused it
  no_face,
  face_too_small,
  face_cut_off,
  head_turned,
  head_tilted,
  eyes_closed,         ///< no eye layer can show through closed lids
  face_index_out_of_range,
  model_missing,       ///< dlib's landmark model cannot be found
  bad_option,
};

struct PrepError {
  PrepErrorCode code = PrepErrorCode::not_an_image;
  std::string message;
};

}  // namespace fw::photo
