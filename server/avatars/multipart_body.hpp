#pragma once
// The parts of a multipart/form-data body (RFC 7578), as POST /api/avatars
// takes a package and the photo it was prepared from in one upload. Only
// what that needs: each part's name and Content-Type; no nesting, no
// transfer encodings, no file names.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace fw::server {

struct MultipartPart {
  std::string content_type;            ///< empty when the part names none
  std::span<const std::uint8_t> data;  ///< a view into the body
};

/// The boundary from a Content-Type of `multipart/form-data; boundary=...`,
/// quoted or not; empty when the type is another or has no boundary.
std::string multipart_boundary(std::string_view content_type);

/// Splits `body` at `boundary` into parts by their form name.
/// @return false and `error` (what is malformed, for the uploader) when the
///         body is not well formed or names a part twice
bool read_multipart(std::span<const std::uint8_t> body, const std::string& boundary,
                    std::map<std::string, MultipartPart>& parts, std::string& error);

}  // namespace fw::server
