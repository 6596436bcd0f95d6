#include "fw/render/offscreen_context.hpp"

// gl.hpp before OSMesa's header, which includes GL without the prototypes.
#include "gl.hpp"

#include <GL/osmesa.h>

namespace fw::render {

struct OffscreenContext::Impl {
  OSMesaContext context = nullptr;
  // OSMesa needs a buffer to make a context current; the renderer draws into
  // framebuffer objects of its own size, so a tiny one is enough.
  std::vector<unsigned char> buffer = std::vector<unsigned char>(4 * 4 * 4);
};

std::unique_ptr<OffscreenContext> OffscreenContext::create(std::string& error) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  std::unique_ptr<OffscreenContext> self(new OffscreenContext());
  self->impl_ = std::make_unique<Impl>();
  self->impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!self->impl_->context) {
    error = "OSMesa could not create an OpenGL 3.3 core context (is libosmesa6 from Mesa >= 20 installed?)";
    return nullptr;
  }
  self->make_current();
  return self;
}

OffscreenContext::~OffscreenContext() {
  if (!impl_ || !impl_->context) return;
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // release the buffer before the context goes
  OSMesaDestroyContext(impl_->context);
}

void OffscreenContext::make_current() {
  OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, 4, 4);
}

std::string OffscreenContext::renderer_name() {
  make_current();
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "unknown";
}

}  // namespace fw::render
