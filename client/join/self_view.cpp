#include "self_view.hpp"

#include "fw/model/avatar_package.hpp"
#include "fw/render/image_codec.hpp"
#include "fw/render/jpeg_codec.hpp"

namespace fw::client {
namespace {

constexpr int kMaxSelfPhotoSide = 1024;

}  // namespace

bool set_self_look(RoomView& view, const OwnAvatar& own, std::string& error) {
  std::shared_ptr<render::AvatarAppearance> appearance;
  bool ok = true;
  if (!own.package.empty()) {
    model::AvatarPackage package;
    appearance = std::make_shared<render::AvatarAppearance>();
    if (!model::parse_avatar_package(own.package, package, error) ||
        !render::load_avatar_appearance(package, *appearance, error)) {
      appearance.reset();
      ok = false;
    }
  }
  model::RgbaImage photo;
  if (!own.photo.empty()) {
    std::string photo_error;
    // own_avatar re-encodes every photo as a JPEG; anything else is read too.
    const bool decoded = render::is_jpeg(own.photo) ? render::decode_jpeg(own.photo, kMaxSelfPhotoSide, photo, photo_error)
                                                    : render::decode_image(own.photo, kMaxSelfPhotoSide, photo, photo_error);
    if (!decoded) photo = {};
  }
  view.set_self_look(std::move(appearance), std::move(photo));
  return ok;
}

bool show_self_view(RoomView& view, FrameOutputs& outputs, const std::string& your_name, std::string& error) {
  RoomScene scene;
  scene.your_name = your_name;
  scene.now = std::chrono::steady_clock::now();
  return outputs.write(view.render(scene), error);
}

}  // namespace fw::client
