#pragma once
// Base64url without padding (RFC 4648 section 5), with one spelling per
// value: a decoder that accepted several spellings of the same bytes would
// let a signed token be altered without breaking its signature.
#include <string>
#include <string_view>

namespace fw::server {

std::string base64url(std::string_view bytes);
/// The bytes `text` spells; false if it is not base64url or not the
/// canonical spelling (unused low bits set, or a length of 4k+1).
bool from_base64url(std::string_view text, std::string& out);

}  // namespace fw::server
