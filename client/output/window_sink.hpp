#pragma once
// Room frames in a window on the X display (Xlib: the frames are rendered
// offscreen by OSMesa and copied into the window). Built when Xlib is
// there; without a display, create() says so.
#include <memory>
#include <string>

#include "frame_sink.hpp"

namespace fw::client {

class WindowSink : public FrameSink {
 public:
  /// A window of width x height titled `title`; nullptr and `error` when no
  /// display can be opened (DISPLAY unset, or a build without Xlib).
  static std::unique_ptr<WindowSink> create(int width, int height, const std::string& title, std::string& error);
  ~WindowSink() override;
  /// false once the person closed the window.
  bool write(const model::RgbaImage& frame, std::string& error) override;

  struct Impl;
 private:
  explicit WindowSink(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::client
