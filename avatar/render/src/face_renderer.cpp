#include "fw/render/face_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "fw/render/offscreen_context.hpp"
#include "gpu_resources.hpp"

namespace fw::embedded {
extern const std::string_view face_vert;  // shaders/face.vert
extern const std::string_view face_frag;  // shaders/face.frag
}  // namespace fw::embedded

namespace fw::render {
namespace {

constexpr int kMinSize = 16, kMaxSize = 4096;
// Skin and mouth keep the photo's own light: no highlight of their own.
constexpr float kSkinSpecular = 0.0f, kEyeSpecular = 0.5f, kMouthSpecular = 0.0f;

struct GpuFace {
  GpuMesh skin, mouth;
  GpuMesh head;  // the shell behind the face, in the skin's texture; moves only with the head pose
  GpuMesh eye_covers;  // non-masking mode only: the eye holes filled, on the skin's vertices
  bool eye_layer = true;
  std::array<GpuMesh, 2> eyes;
  std::array<glm::vec3, 2> eye_centres{};
  std::vector<glm::uvec3> skin_triangles;  // for normals when the shape changes
  Texture skin_texture, eye_texture, mouth_texture, closed_lid, masks_a, masks_b;
  glm::vec4 closed_lid_rect{0.0f};
};

// Where the uniforms of the one shader program live.
struct Uniforms {
  GLint model = -1, view_projection = -1, camera_position = -1, light_direction = -1, specular = -1, texture = -1;
  GLint layer = -1, closed_lid = -1, closed_lid_rect = -1, lid_closure = -1, masks_a = -1, masks_b = -1,
        blush_a = -1, blush_sides = -1, pallor = -1, encode_srgb = -1, alpha_to_coverage = -1;
};

enum Layer : GLint { kSkinLayer = 0, kEyeLayer = 1, kMouthLayer = 2 };
// Texture units: the part's own texture, then the skin's extra ones.
enum Unit : GLint { kMainUnit = 0, kClosedLidUnit = 1, kMasksAUnit = 2, kMasksBUnit = 3 };

// A 1x1 black image: "no effect" for a missing closed lid or mask.
model::RgbaImage or_black(const model::RgbaImage& image) {
  if (image.width > 0) return image;
  model::RgbaImage black(1, 1);
  black.pixels[3] = 255;
  return black;
}

glm::vec3 srgb_to_linear(glm::vec3 c) {
  const auto channel = [](float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

}  // namespace

struct FaceRenderer::Impl {
  RendererOptions options;
  std::unique_ptr<OffscreenContext> context;
  Program program;
  Uniforms uniforms;
  // Multisampled target drawn into, then resolved into a plain one to read.
  Framebuffer draw_framebuffer, resolve_framebuffer;
  Renderbuffer draw_colour, draw_depth, resolve_colour;
  GLsizei samples = 0;
  std::vector<GpuFace> faces;

  bool set_up_framebuffers(std::string& error);
  void draw_mesh(const GpuMesh& mesh, const Texture& texture, const glm::mat4& model, float specular, Layer layer);
};

bool FaceRenderer::Impl::set_up_framebuffers(std::string& error) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(options.samples, 0, max_samples);
  const GLsizei w = options.width, h = options.height;

  draw_colour = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, draw_colour.get());
  // sRGB targets: the shader works in linear light, the framebuffer
  // encodes (GL_FRAMEBUFFER_SRGB) and multisamples resolve in linear light.
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_SRGB8_ALPHA8, w, h);
  draw_depth = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, draw_depth.get());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
  draw_framebuffer = generate<Framebuffer, glGenFramebuffers>();
  glBindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, draw_depth.get());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the GL driver cannot render into a " + std::to_string(w) + "x" + std::to_string(h) + " framebuffer";
    return false;
  }
  resolve_colour = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_colour.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_SRGB8_ALPHA8, w, h);
  resolve_framebuffer = generate<Framebuffer, glGenFramebuffers>();
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_framebuffer.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour.get());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the GL driver cannot create the resolve framebuffer";
    return false;
  }
  return true;
}

void FaceRenderer::Impl::draw_mesh(const GpuMesh& mesh, const Texture& texture, const glm::mat4& model,
                                   float specular, Layer layer) {
  glUniformMatrix4fv(uniforms.model, 1, GL_FALSE, glm::value_ptr(model));
  glUniform1f(uniforms.specular, specular);
  glUniform1i(uniforms.layer, layer);
  glActiveTexture(GL_TEXTURE0 + kMainUnit);
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glBindVertexArray(mesh.vertex_array.get());
  glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
}

FaceRenderer::FaceRenderer() : impl_(std::make_unique<Impl>()) {}
FaceRenderer::~FaceRenderer() {
  // GL objects must go while their context is current, and before it.
  if (impl_->context) impl_->context->make_current();
  auto context = std::move(impl_->context);
  impl_.reset();
}

std::unique_ptr<FaceRenderer> FaceRenderer::create(const RendererOptions& options, std::string& error) {
  if (options.width < kMinSize || options.width > kMaxSize || options.height < kMinSize ||
      options.height > kMaxSize) {
    error = "image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " is out of range; use 16..4096 pixels on each side";
    return nullptr;
  }
  std::unique_ptr<FaceRenderer> self(new FaceRenderer());
  Impl& impl = *self->impl_;
  impl.options = options;
  impl.context = OffscreenContext::create(error);
  if (!impl.context) return nullptr;
  auto program = build_program(embedded::face_vert, embedded::face_frag, error);
  if (!program) return nullptr;
  impl.program = std::move(*program);
  const GLuint p = impl.program.get();
  const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
  impl.uniforms = {at("u_model"),      at("u_view_projection"), at("u_camera_position"), at("u_light_direction"),
                   at("u_specular"),   at("u_texture"),         at("u_layer"),           at("u_closed_lid"),
                   at("u_closed_lid_rect"), at("u_lid_closure"), at("u_masks_a"),         at("u_masks_b"),
                   at("u_blush_a"),     at("u_blush_sides"),     at("u_pallor"),          at("u_encode_srgb"),
                   at("u_alpha_to_coverage")};
  if (!impl.set_up_framebuffers(error)) return nullptr;
  return self;
}

FaceId FaceRenderer::add_face(const model::GenericFace& face, const FaceTextures& textures) {
  impl_->context->make_current();
  GpuFace gpu;
  gpu.skin = upload_mesh(face.skin);
  gpu.mouth = upload_mesh(face.mouth_cavity);
  gpu.head = upload_mesh(face.head.mesh);
  for (std::size_t side = 0; side < 2; ++side) {
    gpu.eyes[side] = upload_mesh(face.eyes[side].mesh);
    gpu.eye_centres[side] = face.eyes[side].centre;
  }
  gpu.skin_triangles = face.skin.triangles;
  gpu.eye_layer = textures.eye.width > 0;
  if (!gpu.eye_layer) {
    std::vector<glm::uvec3> fans;
    for (const auto& hole : face.eye_holes)
      for (std::size_t i = 1; i + 1 < hole.size(); ++i) fans.emplace_back(hole[0], hole[i], hole[i + 1]);
    gpu.eye_covers = share_vertices(gpu.skin, fans);
  }
  gpu.skin_texture = upload_texture(textures.skin, TexelEncoding::srgb_colour);
  gpu.eye_texture = upload_texture(or_black(textures.eye), TexelEncoding::srgb_colour);
  gpu.mouth_texture = upload_texture(textures.mouth, TexelEncoding::srgb_colour);
  gpu.closed_lid = upload_texture(or_black(textures.closed_lid), TexelEncoding::srgb_colour);
  gpu.closed_lid_rect = textures.closed_lid.width > 0 ? textures.closed_lid_rect : glm::vec4(0.0f);
  gpu.masks_a = upload_texture(or_black(textures.masks_a), TexelEncoding::linear_data);
  gpu.masks_b = upload_texture(or_black(textures.masks_b), TexelEncoding::linear_data);
  impl_->faces.push_back(std::move(gpu));
  return static_cast<FaceId>(impl_->faces.size() - 1);
}

void FaceRenderer::set_face_shape(FaceId id, std::span<const glm::vec3> positions, std::span<const glm::vec2> uvs) {
  if (id >= impl_->faces.size()) return;
  impl_->context->make_current();
  GpuFace& face = impl_->faces[id];
  model::Mesh mesh;
  mesh.positions.assign(positions.begin(), positions.end());
  mesh.uvs.assign(uvs.begin(), uvs.end());
  mesh.triangles = face.skin_triangles;
  update_mesh(face.skin, mesh);
}

model::RgbaImage FaceRenderer::render(std::span<const FaceDraw> draws, const Camera& camera) {
  Impl& impl = *impl_;
  impl.context->make_current();
  const int w = impl.options.width, h = impl.options.height;
  glBindFramebuffer(GL_FRAMEBUFFER, impl.draw_framebuffer.get());
  glViewport(0, 0, w, h);
  // The background is given in sRGB like any colour; the framebuffer encodes.
  const glm::vec3 background = srgb_to_linear(impl.options.background);
  glEnable(GL_FRAMEBUFFER_SRGB);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // a turned head shows the inside of its rim
  // Soft edges of the eye holes as coverage; what is drawn stays opaque.
  const bool alpha_to_coverage = impl.samples > 0;
  if (alpha_to_coverage) {
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  }

  glUseProgram(impl.program.get());
  glUniformMatrix4fv(impl.uniforms.view_projection, 1, GL_FALSE, glm::value_ptr(camera.view_projection()));
  glUniform3fv(impl.uniforms.camera_position, 1, glm::value_ptr(camera.position));
  const glm::vec3 light(0.45f, 0.6f, 0.9f);  // key light above and to the viewer's right
  glUniform3fv(impl.uniforms.light_direction, 1, glm::value_ptr(light));
  glUniform1i(impl.uniforms.texture, kMainUnit);
  glUniform1i(impl.uniforms.encode_srgb, 0);
  glUniform1i(impl.uniforms.alpha_to_coverage, alpha_to_coverage ? 1 : 0);
  glUniform1i(impl.uniforms.closed_lid, kClosedLidUnit);
  glUniform1i(impl.uniforms.masks_a, kMasksAUnit);
  glUniform1i(impl.uniforms.masks_b, kMasksBUnit);

  for (const FaceDraw& draw : draws) {
    if (draw.face >= impl.faces.size()) continue;  // an id from another renderer: nothing to draw
    const GpuFace& face = impl.faces[draw.face];
    glActiveTexture(GL_TEXTURE0 + kClosedLidUnit);
    glBindTexture(GL_TEXTURE_2D, face.closed_lid.get());
    glActiveTexture(GL_TEXTURE0 + kMasksAUnit);
    glBindTexture(GL_TEXTURE_2D, face.masks_a.get());
    glActiveTexture(GL_TEXTURE0 + kMasksBUnit);
    glBindTexture(GL_TEXTURE_2D, face.masks_b.get());
    glUniform4fv(impl.uniforms.closed_lid_rect, 1, glm::value_ptr(face.closed_lid_rect));
    glUniform2fv(impl.uniforms.lid_closure, 1, glm::value_ptr(draw.lid_closure));
    glUniform4f(impl.uniforms.blush_a, draw.blush[0], draw.blush[1], draw.blush[2], draw.blush[3]);
    glUniform1f(impl.uniforms.blush_sides, draw.blush[4]);
    glUniform1f(impl.uniforms.pallor, draw.pallor);
    // Nearest first: what lies behind (the eyeballs, the mouth cavity, the
    // head shell behind the face) then fails the depth test before it is
    // shaded, which a software renderer feels.
    impl.draw_mesh(face.skin, face.skin_texture, draw.model, kSkinSpecular, kSkinLayer);
    if (!face.eye_layer) {
      impl.draw_mesh(face.eye_covers, face.skin_texture, draw.model, kSkinSpecular, kSkinLayer);
    } else {
      for (std::size_t side = 0; side < 2; ++side) {
        const glm::vec2 yaw_pitch = draw.eye_yaw_pitch_rad[side];
        const glm::mat4 eye_model = draw.model * eye_transform(face.eye_centres[side], yaw_pitch.x, yaw_pitch.y);
        impl.draw_mesh(face.eyes[side], face.eye_texture, eye_model, kEyeSpecular, kEyeLayer);
      }
    }
    impl.draw_mesh(face.mouth, face.mouth_texture, draw.model, kMouthSpecular, kMouthLayer);
    impl.draw_mesh(face.head, face.skin_texture, draw.model, kSkinSpecular, kSkinLayer);
  }
  glBindVertexArray(0);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);

  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl.draw_framebuffer.get());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, impl.resolve_framebuffer.get());
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl.resolve_framebuffer.get());
  model::RgbaImage image(w, h);
  std::vector<std::uint8_t> bottom_up(image.pixels.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h; ++y)
    std::copy_n(bottom_up.data() + static_cast<std::size_t>(h - 1 - y) * row, row, image.at(0, y));
  return image;
}

std::string FaceRenderer::renderer_name() { return impl_->context->renderer_name(); }
int FaceRenderer::width() const { return impl_->options.width; }
int FaceRenderer::height() const { return impl_->options.height; }

}  // namespace fw::render
