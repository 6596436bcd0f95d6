#pragma once
// An OSMesa (software, llvmpipe) OpenGL 3.3 core context: rendering with no
// display and no GPU.
#include <memory>
#include <string>
#include <vector>

namespace fw::render {

class OffscreenContext {
 public:
  /// Creates a GL 3.3 core context. nullptr and `error` set if OSMesa cannot
  /// (missing libOSMesa, or a Mesa without core-profile support).
  static std::unique_ptr<OffscreenContext> create(std::string& error);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// Makes this context current on the calling thread.
  void make_current();
  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer_name();

 private:
  OffscreenContext() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::render
