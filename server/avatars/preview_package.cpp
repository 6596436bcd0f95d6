#include "preview_package.hpp"

#include "package_images.hpp"

namespace fw::server {

bool make_preview_package(const model::AvatarPackage& package, std::vector<std::uint8_t>& preview, std::string& error) {
  // Sides chosen so a face reads at a glance while the whole stays near 2 KB,
  // most of it the fit (which a preview cannot shrink: it is the face's shape).
  struct Member {
    model::PackageImage model::AvatarPackage::*image;
    int max_side;
    const char* name;
  };
  static constexpr Member kMembers[] = {
      {&model::AvatarPackage::face_texture, 40, "face texture"}, {&model::AvatarPackage::closed_lid, 12, "closed lid"},
      {&model::AvatarPackage::eye, 12, "eye"},                   {&model::AvatarPackage::mouth, 8, "mouth"},
      {&model::AvatarPackage::colour_masks_a, 8, "colour masks"}, {&model::AvatarPackage::colour_masks_b, 8, "colour masks"},
      {&model::AvatarPackage::preview, 8, "preview"}};
  model::AvatarPackage small = package;
  for (const Member& member : kMembers) {
    auto shrunk = shrink_package_image(package.*member.image, member.max_side, 20);
    if (!shrunk) {
      error = std::string("the package's ") + member.name + " image does not decode";
      return false;
    }
    small.*member.image = std::move(*shrunk);
  }
  preview = model::serialize_avatar_package(small);
  return true;
}

}  // namespace fw::server
