#include "fw/render/face_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "fw/model/eye_socket.hpp"
#include "fw/model/head_back.hpp"
#include "fw/model/mesh.hpp"
#include "fw/render/offscreen_context.hpp"
#include "gpu_resources.hpp"
#include "opaque_texels.hpp"
#include "screen_rect.hpp"
#include "shader_variants.hpp"

namespace fw::embedded {
extern const std::string_view face_vert;  // shaders/face.vert
extern const std::string_view face_frag;  // shaders/face.frag
}  // namespace fw::embedded

namespace fw::render {

// One face's GL resources. Outside the anonymous namespace: Impl, which has
// linkage, holds them.
struct GpuFace {
  GpuMesh skin, mouth;
  GpuMesh head;  // the shell behind the face, in the skin's texture; moves only with the head pose
  GpuMesh eye_covers;  // non-masking mode only: the eye holes filled, on the skin's vertices
  bool eye_layer = true;
  model::TextureLight light = model::TextureLight::photo;  // chooses every part's variant
  std::array<GpuMesh, 2> eyes;
  std::array<GpuMesh, 2> eye_sockets;     // fw/model/eye_socket.hpp: drawn from inside, within the hole
  std::array<GpuMesh, 2> eye_hole_fans;   // each hole spanned, on the skin's vertices: marks where it is
  std::array<glm::vec3, 2> eye_centres{};
  std::vector<glm::uvec3> skin_triangles;  // for normals when the shape changes
  std::vector<glm::vec3> skin_positions;   // the current shape's, for the openings' rectangles
  std::array<std::vector<std::uint32_t>, 2> eye_holes;
  std::vector<std::uint32_t> mouth_slit;
  // Model-space box around everything drawn for the face but the skin (the
  // shell, the mouth cavity, the eyeballs however they turn), and around
  // all of it with the skin's current shape.
  glm::vec3 rigid_low{0.0f}, rigid_high{0.0f}, box_low{0.0f}, box_high{0.0f};
  Texture skin_texture, eye_texture, mouth_texture, closed_lid, masks_a, masks_b;
  // Which of the skin's and the shell's triangles read only opaque texels
  // (opaque_texels.hpp), sorted first in each frame; the skin's uvs move
  // with its shape, so its opacity is found again then.
  OpaqueTexels skin_opaque;
  TexelOpacity skin_opacity, head_opacity;
  std::vector<glm::vec2> skin_uvs;
  std::vector<glm::vec3> head_positions;
  std::vector<glm::vec2> head_uvs;
  glm::vec4 closed_lid_rect{0.0f};
};

namespace {

constexpr int kMinSize = 16, kMaxSize = 4096;
// The eye's sheen and catch-light (face.frag): at 1 the catch-light is as
// bright as a white surface facing the key light, so it reads as near white
// on any iris.
constexpr float kEyeSpecular = 1.0f;
// The scale of the skin's specular lobe on albedo faces (face.frag): the
// face's skin only, never the head shell.
constexpr float kSkinSpecular = 2.5f;
// Toward the key light: above and to the viewer's right, as a portrait's
// key light usually is; unit length, as the shaders expect.
const glm::vec3 kKeyLight = glm::normalize(glm::vec3(0.45f, 0.6f, 0.9f));

// Texture units: the part's own texture, then the skin's extra ones.
enum Unit : GLint { kMainUnit = 0, kClosedLidUnit = 1, kMasksAUnit = 2, kMasksBUnit = 3 };

// A 1x1 black image: "no effect" for a missing closed lid or mask.
model::RgbaImage or_black(const model::RgbaImage& image) {
  if (image.width > 0) return image;
  model::RgbaImage black(1, 1);
  black.pixels[3] = 255;
  return black;
}

}  // namespace

struct FaceRenderer::Impl {
  RendererOptions options;
  std::unique_ptr<OffscreenContext> context;
  std::array<ShaderVariant, kShaderCount> shaders;
  // Multisampled target drawn into, then resolved into a plain one to read.
  Framebuffer draw_framebuffer, resolve_framebuffer;
  Renderbuffer draw_colour, draw_depth, resolve_colour;
  GLsizei samples = 0;
  std::vector<GpuFace> faces;
  std::size_t current_variant = 0;  // the program in use, for profiles
  FrameProfile* profile = nullptr;
  std::chrono::steady_clock::time_point part_start;
  // Profiling only: waits for what was asked of GL since the last part
  // ended and books its time to `part` (and to the program in use if
  // `with_variant`).
  void end_part(std::string_view part, bool with_variant);

  bool set_up_framebuffers(std::string& error);
  const ShaderUniforms& use(std::size_t variant) {
    glUseProgram(shaders[variant].program.get());
    current_variant = variant;
    return shaders[variant].uniforms;
  }
  const ShaderUniforms& use(PartShader kind, model::TextureLight light) { return use(shader_index(kind, light)); }
  void set_frame_uniforms(const Camera& camera);
  std::array<std::uint8_t, 4> background_texel{};  // the background as the targets store it
  void draw_face(GpuFace& face, const FaceDraw& draw, const Camera& camera);
  void draw_socket(const GpuFace& face, std::size_t side, const ShaderUniforms& eye, const glm::mat4& model);
  // Sorts `mesh`'s triangles that read only opaque texels in this frame first.
  void sort_for_frame(GpuMesh& mesh, const TexelOpacity& opacity, std::span<const glm::vec3> positions,
                      std::span<const glm::vec2> uvs, const glm::mat4& mvp);
  std::vector<glm::uvec3> sorted_triangles;  // scratch
  void draw_mesh(const GpuMesh& mesh, const Texture& texture, const ShaderUniforms& uniforms, const glm::mat4& model);
  PixelRect drawn_rect(std::span<const FaceDraw> draws, const Camera& camera) const;
  void scissor_to_opening(const GpuFace& face, std::span<const std::uint32_t> outline, const glm::mat4& mvp);
};

void FaceRenderer::Impl::end_part(std::string_view part, bool with_variant) {
  if (!profile) return;
  glFinish();
  const auto now = std::chrono::steady_clock::now();
  profile->add(part, with_variant ? shader_name(current_variant) : std::string(),
               std::chrono::duration<double>(now - part_start).count());
  part_start = now;
}

void FaceRenderer::Impl::scissor_to_opening(const GpuFace& face, std::span<const std::uint32_t> outline,
                                            const glm::mat4& mvp) {
  std::vector<glm::vec3> points;
  points.reserve(outline.size());
  for (std::uint32_t v : outline)
    if (v < face.skin_positions.size()) points.push_back(face.skin_positions[v]);
  const auto rect = screen_rect(points, mvp, options.width, options.height, 0.25f);
  if (!rect) return;  // drawn whole
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect->x, rect->y, rect->width, rect->height);
}

bool FaceRenderer::Impl::set_up_framebuffers(std::string& error) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(options.samples, 0, max_samples);
  const GLsizei w = options.width, h = options.height;

  draw_colour = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, draw_colour.get());
  // Plain 8-bit targets: the shader encodes its linear light to sRGB (see
  // face.frag on why not an sRGB framebuffer).
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
  draw_depth = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, draw_depth.get());
  // A float depth: as fine as 24 bits over [0, 1] or finer, the same
  // pixels, and measured a hundredth cheaper per frame in llvmpipe, which
  // tests depth for every sample. The stencil marks an eye's open hole
  // (draw_socket).
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH32F_STENCIL8, w, h);
  draw_framebuffer = generate<Framebuffer, glGenFramebuffers>();
  glBindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, draw_depth.get());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the GL driver cannot render into a " + std::to_string(w) + "x" + std::to_string(h) + " framebuffer";
    return false;
  }
  resolve_colour = generate<Renderbuffer, glGenRenderbuffers>();
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_colour.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  resolve_framebuffer = generate<Framebuffer, glGenFramebuffers>();
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_framebuffer.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour.get());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the GL driver cannot create the resolve framebuffer";
    return false;
  }
  return true;
}

PixelRect FaceRenderer::Impl::drawn_rect(std::span<const FaceDraw> draws, const Camera& camera) const {
  const PixelRect whole{0, 0, options.width, options.height};
  PixelRect drawn;
  for (const FaceDraw& draw : draws) {
    if (draw.face >= faces.size()) continue;
    const GpuFace& face = faces[draw.face];
    std::array<glm::vec3, 8> corners;
    for (std::size_t i = 0; i < corners.size(); ++i)
      corners[i] = {(i & 1) ? face.box_high.x : face.box_low.x, (i & 2) ? face.box_high.y : face.box_low.y,
                    (i & 4) ? face.box_high.z : face.box_low.z};
    const auto rect = screen_rect(corners, camera.view_projection() * draw.model, options.width, options.height, 0.0f);
    if (!rect) return whole;
    drawn = union_of(drawn, *rect);
  }
  return drawn;
}

namespace {

// Grows the box `low`..`high` to hold `points`.
void grow_box(std::span<const glm::vec3> points, glm::vec3& low, glm::vec3& high) {
  for (const glm::vec3& p : points) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
}

void bind_texture(Unit unit, const Texture& texture) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture.get());
}

}  // namespace

void FaceRenderer::Impl::draw_mesh(const GpuMesh& mesh, const Texture& texture, const ShaderUniforms& uniforms,
                                   const glm::mat4& model) {
  glUniformMatrix4fv(uniforms.model, 1, GL_FALSE, glm::value_ptr(model));
  glActiveTexture(GL_TEXTURE0 + kMainUnit);
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glBindVertexArray(mesh.vertex_array.get());
  if (samples == 0) {
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    return;
  }
  // Triangles that read only opaque texels cover every sample with alpha to
  // coverage or without: without, llvmpipe does less (opaque_texels.hpp).
  if (mesh.opaque_index_count > 0) {
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glDrawElements(GL_TRIANGLES, mesh.opaque_index_count, GL_UNSIGNED_INT, nullptr);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  }
  if (mesh.index_count > mesh.opaque_index_count)
    glDrawElements(GL_TRIANGLES, mesh.index_count - mesh.opaque_index_count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(mesh.opaque_index_count) * sizeof(GLuint)));
}

void FaceRenderer::Impl::set_frame_uniforms(const Camera& camera) {
  for (std::size_t i = 0; i < kShaderCount; ++i) {
    const ShaderUniforms& u = use(i);
    glUniformMatrix4fv(u.view_projection, 1, GL_FALSE, glm::value_ptr(camera.view_projection()));
    glUniform3fv(u.camera_position, 1, glm::value_ptr(camera.position));
    glUniform3fv(u.light_direction, 1, glm::value_ptr(kKeyLight));
    glUniform1i(u.texture, kMainUnit);
    glUniform1i(u.closed_lid, kClosedLidUnit);
    glUniform1i(u.masks_a, kMasksAUnit);
    glUniform1i(u.masks_b, kMasksBUnit);
    glUniform1f(u.specular, kEyeSpecular);
  }
}

void FaceRenderer::Impl::draw_socket(const GpuFace& face, std::size_t side, const ShaderUniforms& eye,
                                     const glm::mat4& model) {
  // Where the hole is open (the skin and the lids in front of it left it
  // so): the stencil marks it, nothing else is written.
  // Called in the eyes' loop, back faces culled; the fan faces either way.
  glDisable(GL_CULL_FACE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  draw_mesh(face.eye_hole_fans[side], face.eye_texture, eye, model);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  // The socket's far wall there, for the lines of sight that pass beside
  // the eyeball: front faces culled, it never covers the eyeball, and a
  // wall has no wet sheen. Elsewhere (the temple, where the skin curves
  // back behind the sphere) the stencil keeps it out.
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glUniform1f(eye.specular, 0.0f);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  draw_mesh(face.eye_sockets[side], face.eye_texture, eye, model);
  glCullFace(GL_BACK);
  glUniform1f(eye.specular, kEyeSpecular);
  glClear(GL_STENCIL_BUFFER_BIT);  // within the opening's scissor: the next hole starts unmarked
  glDisable(GL_STENCIL_TEST);
}

void FaceRenderer::Impl::sort_for_frame(GpuMesh& mesh, const TexelOpacity& opacity, std::span<const glm::vec3> positions,
                                        std::span<const glm::vec2> uvs, const glm::mat4& mvp) {
  if (samples == 0) return;  // no alpha to coverage to spare
  const std::size_t opaque = sort_opaque_first(opacity, positions, uvs, mvp,
                                               glm::vec2(options.width, options.height), sorted_triangles);
  set_triangle_order(mesh, sorted_triangles, opaque);
}

void FaceRenderer::Impl::draw_face(GpuFace& face, const FaceDraw& draw, const Camera& camera) {
  // Nearest first: what lies behind (the eyeballs, the mouth cavity, the
  // head shell behind the face) then fails the depth test before it is
  // shaded, which a software renderer feels (llvmpipe only without
  // multisampling; with it, the openings' scissors do what they can).
  const bool blood = std::any_of(draw.blush.begin(), draw.blush.end(), [](float b) { return b > 0.0f; }) ||
                     draw.pallor > 0.0f;
  // A face without a closed-lid layer has an empty rectangle: nothing to fade in.
  const bool lids_closing = face.closed_lid_rect != glm::vec4(0.0f) &&
                            (draw.lid_closure.x > 0.0f || draw.lid_closure.y > 0.0f);
  const ShaderUniforms& skin = use(skin_shader(lids_closing, blood), face.light);
  if (lids_closing) {
    bind_texture(kClosedLidUnit, face.closed_lid);
    glUniform4fv(skin.closed_lid_rect, 1, glm::value_ptr(face.closed_lid_rect));
    glUniform2fv(skin.lid_closure, 1, glm::value_ptr(draw.lid_closure));
  }
  if (blood) {
    bind_texture(kMasksAUnit, face.masks_a);
    bind_texture(kMasksBUnit, face.masks_b);
    glUniform4f(skin.blush_a, draw.blush[0], draw.blush[1], draw.blush[2], draw.blush[3]);
    glUniform1f(skin.blush_sides, draw.blush[4]);
    glUniform1f(skin.pallor, draw.pallor);
  }
  glUniform1f(skin.skin_specular, kSkinSpecular);
  const glm::mat4 skin_mvp = camera.view_projection() * draw.model;
  sort_for_frame(face.skin, face.skin_opacity, face.skin_positions, face.skin_uvs, skin_mvp);
  draw_mesh(face.skin, face.skin_texture, skin, draw.model);
  end_part("skin", true);
  if (!face.eye_layer) {
    draw_mesh(face.eye_covers, face.skin_texture, skin, draw.model);
    end_part("eye covers", true);
  } else {
    const ShaderUniforms& eye = use(PartShader::eye, face.light);
    // An eyeball is a sphere but for a small cap at its back, with its
    // triangles facing out: seen through its hole, its far half is hidden
    // by its near half and need not be drawn (2 % of a frame).
    glEnable(GL_CULL_FACE);
    for (std::size_t side = 0; side < 2; ++side) {
      // Shut, the lids hide the eye; drawn, its turning changed a pixel or
      // two where the closed lids' corner covers part of a pixel.
      if (draw.lid_closure[static_cast<glm::length_t>(side)] >= 1.0f) continue;
      const glm::vec2 yaw_pitch = draw.eye_yaw_pitch_rad[side];
      const glm::mat4 eye_model = draw.model * eye_transform(face.eye_centres[side], yaw_pitch.x, yaw_pitch.y);
      scissor_to_opening(face, face.eye_holes[side], skin_mvp);
      draw_mesh(face.eyes[side], face.eye_texture, eye, eye_model);
      draw_socket(face, side, eye, draw.model);
      glDisable(GL_SCISSOR_TEST);
    }
    glDisable(GL_CULL_FACE);
    end_part("eyes", true);
  }
  const ShaderUniforms& matte = use(PartShader::matte, face.light);
  scissor_to_opening(face, face.mouth_slit, skin_mvp);
  draw_mesh(face.mouth, face.mouth_texture, matte, draw.model);
  glDisable(GL_SCISSOR_TEST);
  end_part("mouth", true);
  // The shell is closed wherever it can be seen, with its triangles facing
  // out: its far side need not be drawn at all.
  glEnable(GL_CULL_FACE);
  sort_for_frame(face.head, face.head_opacity, face.head_positions, face.head_uvs, skin_mvp);
  draw_mesh(face.head, face.skin_texture, matte, draw.model);
  glDisable(GL_CULL_FACE);
  end_part("shell", true);
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
  if (!impl.set_up_framebuffers(error)) return nullptr;
  // The background as GL stores it (its own rounding), for the pixels no
  // face can reach, which render() fills without GL.
  glBindFramebuffer(GL_FRAMEBUFFER, impl.resolve_framebuffer.get());
  glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, impl.background_texel.data());
  auto shaders = build_part_shaders(embedded::face_vert, embedded::face_frag, impl.samples == 0, error);
  if (!shaders) return nullptr;
  impl.shaders = std::move(*shaders);
  return self;
}

FaceId FaceRenderer::add_face(const model::GenericFace& face, const FaceTextures& textures) {
  impl_->context->make_current();
  GpuFace gpu;
  gpu.skin = upload_mesh(face.skin);
  gpu.mouth = upload_mesh(face.mouth_cavity);
  gpu.head = upload_mesh(face.head.mesh,
                         model::photo_light_normals(face.head.mesh, model::welded_vertex_normals(face.head.mesh)));
  for (std::size_t side = 0; side < 2; ++side) {
    gpu.eyes[side] = upload_mesh(face.eyes[side].mesh);
    gpu.eye_sockets[side] = upload_mesh(model::eye_socket_mesh(face, side));
    gpu.eye_centres[side] = face.eyes[side].centre;
  }
  gpu.skin_triangles = face.skin.triangles;
  gpu.skin_positions = face.skin.positions;
  gpu.rigid_low = glm::vec3(1e30f);
  gpu.rigid_high = glm::vec3(-1e30f);
  grow_box(face.head.mesh.positions, gpu.rigid_low, gpu.rigid_high);
  grow_box(face.mouth_cavity.positions, gpu.rigid_low, gpu.rigid_high);
  for (const auto& eye : face.eyes) {
    // Turned about its centre, an eyeball stays within the sphere through its farthest point.
    float reach = 0.0f;
    for (const glm::vec3& p : eye.mesh.positions) reach = std::max(reach, glm::length(p - eye.centre));
    const glm::vec3 around[2] = {eye.centre - reach, eye.centre + reach};
    grow_box(around, gpu.rigid_low, gpu.rigid_high);
  }
  gpu.box_low = gpu.rigid_low;
  gpu.box_high = gpu.rigid_high;
  grow_box(gpu.skin_positions, gpu.box_low, gpu.box_high);
  gpu.eye_holes = face.eye_holes;
  gpu.mouth_slit = face.mouth_slit;
  gpu.eye_layer = textures.eye.width > 0;
  gpu.light = textures.light;
  std::vector<glm::uvec3> fans;
  for (std::size_t side = 0; side < 2; ++side) {
    std::vector<glm::uvec3> hole_fan;
    const auto& hole = face.eye_holes[side];
    for (std::size_t i = 1; i + 1 < hole.size(); ++i) hole_fan.emplace_back(hole[0], hole[i], hole[i + 1]);
    gpu.eye_hole_fans[side] = share_vertices(gpu.skin, hole_fan);
    fans.insert(fans.end(), hole_fan.begin(), hole_fan.end());
  }
  if (!gpu.eye_layer) gpu.eye_covers = share_vertices(gpu.skin, fans);
  // Alpha to coverage is left out where it changes nothing (opaque_texels.hpp):
  // the eyeballs and the mouth cavity are opaque in all but odd textures,
  // the skin and the shell are sorted in each frame.
  const std::vector<MipLevel> skin_levels = square_root_light_mipmaps(textures.skin);
  gpu.skin_texture = upload_colour_levels(skin_levels);
  gpu.skin_opaque = OpaqueTexels(skin_levels);
  gpu.skin_uvs = face.skin.uvs;
  gpu.skin_opacity = texel_opacity(face.skin.triangles, gpu.skin_uvs, gpu.skin_opaque);
  gpu.head_positions = face.head.mesh.positions;
  gpu.head_uvs = face.head.mesh.uvs;
  gpu.head_opacity = texel_opacity(face.head.mesh.triangles, gpu.head_uvs, gpu.skin_opaque);
  const auto opaque_when_all_is = [](const std::vector<MipLevel>& levels, const model::Mesh& mesh, GpuMesh& gpu_mesh) {
    if (texel_opacity(mesh.triangles, mesh.uvs, OpaqueTexels(levels)).all_opaque())
      set_triangle_order(gpu_mesh, mesh.triangles, mesh.triangles.size());
  };
  const std::vector<MipLevel> eye_levels = square_root_light_mipmaps(or_black(textures.eye));
  gpu.eye_texture = upload_colour_levels(eye_levels);
  for (std::size_t side = 0; side < 2; ++side) opaque_when_all_is(eye_levels, face.eyes[side].mesh, gpu.eyes[side]);
  const std::vector<MipLevel> mouth_levels = square_root_light_mipmaps(textures.mouth);
  gpu.mouth_texture = upload_colour_levels(mouth_levels);
  opaque_when_all_is(mouth_levels, face.mouth_cavity, gpu.mouth);
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
  face.skin_uvs = mesh.uvs;
  face.skin_opacity = texel_opacity(face.skin_triangles, face.skin_uvs, face.skin_opaque);
  face.skin_positions = std::move(mesh.positions);
  face.box_low = face.rigid_low;
  face.box_high = face.rigid_high;
  grow_box(face.skin_positions, face.box_low, face.box_high);
}

model::RgbaImage FaceRenderer::render(std::span<const FaceDraw> draws, const Camera& camera) {
  Impl& impl = *impl_;
  impl.context->make_current();
  if (impl.profile) {
    glFinish();
    impl.part_start = std::chrono::steady_clock::now();
    ++impl.profile->frames;
  }
  const int w = impl.options.width, h = impl.options.height;
  glBindFramebuffer(GL_FRAMEBUFFER, impl.draw_framebuffer.get());
  glViewport(0, 0, w, h);
  // Only the rectangle the faces can reach is resolved and read back; the
  // rest of the image is the background. (The clear stays whole: llvmpipe
  // clears a whole target by filling memory, a scissored one by drawing.)
  const PixelRect drawn = impl.drawn_rect(draws, camera);
  model::RgbaImage image(w, h);
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  for (std::size_t i = 0; i < row; i += 4) std::copy_n(impl.background_texel.data(), 4, image.at(0, 0) + i);
  for (int y = 1; y < h; ++y) std::copy_n(image.at(0, 0), row, image.at(0, y));
  impl.end_part("background", false);
  if (drawn.width <= 0 || drawn.height <= 0) return image;
  // Targets store what they are given, and the background is given in sRGB.
  const glm::vec3 background = impl.options.background;
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Only the head shell and the eyeballs are culled (draw_face): the skin
  // is open, and a turned head shows the inside of its rim.
  glCullFace(GL_BACK);
  // Soft edges (the eye holes, the head's outline) as coverage; what is
  // drawn stays opaque.
  const bool alpha_to_coverage = impl.samples > 0;
  if (alpha_to_coverage) {
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  }
  impl.end_part("clear", false);
  impl.set_frame_uniforms(camera);
  for (const FaceDraw& draw : draws) {
    if (draw.face >= impl.faces.size()) continue;  // an id from another renderer: nothing to draw
    impl.draw_face(impl.faces[draw.face], draw, camera);
  }
  glBindVertexArray(0);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);

  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl.draw_framebuffer.get());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, impl.resolve_framebuffer.get());
  const int x0 = drawn.x, y0 = drawn.y, x1 = drawn.x + drawn.width, y1 = drawn.y + drawn.height;
  glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  impl.end_part("resolve", false);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl.resolve_framebuffer.get());
  std::vector<std::uint8_t> bottom_up(static_cast<std::size_t>(drawn.width) * drawn.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x0, y0, drawn.width, drawn.height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  const std::size_t drawn_row = static_cast<std::size_t>(drawn.width) * 4;
  for (int y = y0; y < y1; ++y)
    std::copy_n(bottom_up.data() + static_cast<std::size_t>(y - y0) * drawn_row, drawn_row, image.at(x0, h - 1 - y));
  impl.end_part("readback", false);
  return image;
}

void FaceRenderer::set_profile(FrameProfile* profile) { impl_->profile = profile; }

std::string FaceRenderer::renderer_name() { return impl_->context->renderer_name(); }
int FaceRenderer::width() const { return impl_->options.width; }
int FaceRenderer::height() const { return impl_->options.height; }

}  // namespace fw::render
