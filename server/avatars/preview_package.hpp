#pragma once
// The preview of an avatar package: the same face and fit with tiny
// textures, a couple of kilobytes, so that a client over a slow link shows
// the face at once and the full package follows (PROTOCOL.md, "package chunk").
#include <string>
#include <vector>

#include "fw/model/avatar_package.hpp"

namespace fw::server {

/// @param[in]  package  a parsed, valid package
/// @param[out] preview  the serialised preview package (.fwa)
/// @return false and `error` if an image of the package does not decode
bool make_preview_package(const model::AvatarPackage& package, std::vector<std::uint8_t>& preview, std::string& error);

}  // namespace fw::server
