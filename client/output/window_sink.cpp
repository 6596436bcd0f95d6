#include "window_sink.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#if FW_CLIENT_HAS_X11
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#endif

namespace fw::client {

#if FW_CLIENT_HAS_X11

struct WindowSink::Impl {
  Display* display = nullptr;
  Window window = 0;
  GC gc = nullptr;
  Atom delete_atom = 0;
  XImage* image = nullptr;  // wraps `pixels`
  std::vector<char> pixels;
  int width = 0, height = 0;

  ~Impl() {
    if (image) {
      image->data = nullptr;  // the vector owns the pixels
      XDestroyImage(image);
    }
    if (gc) XFreeGC(display, gc);
    if (window) XDestroyWindow(display, window);
    if (display) XCloseDisplay(display);
  }
};

std::unique_ptr<WindowSink> WindowSink::create(int width, int height, const std::string& title, std::string& error) {
  auto impl = std::make_unique<Impl>();
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    error = "--window needs a display and DISPLAY is not set; use --out DIR (PNG frames) or --y4m - | ffplay - instead";
    return nullptr;
  }
  impl->display = XOpenDisplay(nullptr);
  if (!impl->display) {
    error = std::string("--window: cannot open the display '") + name + "'; use --out DIR or --y4m FILE instead";
    return nullptr;
  }
  Display* d = impl->display;
  const int screen = DefaultScreen(d);
  XVisualInfo visual{};
  if (!XMatchVisualInfo(d, screen, 24, TrueColor, &visual)) {
    error = "--window: the display has no 24-bit TrueColor visual; use --out DIR or --y4m FILE instead";
    return nullptr;
  }
  impl->width = width;
  impl->height = height;
  impl->window = XCreateSimpleWindow(d, RootWindow(d, screen), 0, 0, static_cast<unsigned>(width),
                                     static_cast<unsigned>(height), 0, BlackPixel(d, screen), BlackPixel(d, screen));
  XStoreName(d, impl->window, title.c_str());
  impl->delete_atom = XInternAtom(d, "WM_DELETE_WINDOW", False);
  XSetWMProtocols(d, impl->window, &impl->delete_atom, 1);
  XSelectInput(d, impl->window, StructureNotifyMask);
  XMapWindow(d, impl->window);
  impl->gc = XCreateGC(d, impl->window, 0, nullptr);
  impl->pixels.resize(static_cast<std::size_t>(width) * height * 4);
  impl->image = XCreateImage(d, visual.visual, 24, ZPixmap, 0, impl->pixels.data(), static_cast<unsigned>(width),
                             static_cast<unsigned>(height), 32, 0);
  if (!impl->image) {
    error = "--window: cannot create an image for the display";
    return nullptr;
  }
  XFlush(d);
  return std::unique_ptr<WindowSink>(new WindowSink(std::move(impl)));
}

bool WindowSink::write(const model::RgbaImage& frame, std::string& error) {
  Impl& w = *impl_;
  while (XPending(w.display)) {
    XEvent event;
    XNextEvent(w.display, &event);
    if (event.type == ClientMessage && static_cast<Atom>(event.xclient.data.l[0]) == w.delete_atom) {
      error = "the window was closed";
      return false;
    }
  }
  const int width = std::min(frame.width, w.width), height = std::min(frame.height, w.height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = frame.at(x, y);
      // 24-bit TrueColor visuals put red, green, blue at 0xRRGGBB; XPutPixel handles the byte order.
      XPutPixel(w.image, x, y, (static_cast<unsigned long>(p[0]) << 16) | (static_cast<unsigned long>(p[1]) << 8) | p[2]);
    }
  XPutImage(w.display, w.window, w.gc, w.image, 0, 0, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height));
  XFlush(w.display);
  return true;
}

#else

struct WindowSink::Impl {};

std::unique_ptr<WindowSink> WindowSink::create(int, int, const std::string&, std::string& error) {
  error = "--window: this facewire-client was built without Xlib (libx11-dev); use --out DIR (PNG frames) or "
          "--y4m - | ffplay - instead";
  return nullptr;
}

bool WindowSink::write(const model::RgbaImage&, std::string&) { return false; }

#endif

WindowSink::WindowSink(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
WindowSink::~WindowSink() = default;

}  // namespace fw::client
