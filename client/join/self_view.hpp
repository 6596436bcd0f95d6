#pragma once
// The self view from the first frame: the face the person brings (the
// package they upload, or the photo) is given to the room view before
// anything is uploaded or received, and one frame of it goes out at once.
#include <string>

#include "frame_outputs.hpp"
#include "own_avatar.hpp"
#include "room_view.hpp"

namespace fw::client {

/// Gives `view` the self look of `own` (its package's face, else its photo);
/// false and `error` when the package's face cannot be drawn (the photo and
/// the generic face still can: the view is told what it can show).
bool set_self_look(RoomView& view, const OwnAvatar& own, std::string& error);

/// Renders the room before the server said anything (the self view alone,
/// named `your_name`) and writes it to `outputs`; false and `error` when an
/// output failed.
bool show_self_view(RoomView& view, FrameOutputs& outputs, const std::string& your_name, std::string& error);

}  // namespace fw::client
