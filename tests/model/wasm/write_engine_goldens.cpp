// Writes what the native C++ makes of the engine's test inputs, for the
// browser engine's tests (tests/model/wasm/*.test.mjs) to compare with: run
// by ctest just before them (fixture engine_goldens), from the build's own
// code, so the goldens cannot go stale.
//
//   write_engine_goldens SEED.fwa OUT_DIR
//
// OUT_DIR receives every package (<name>.fwa) and goldens.json: for each
// package, the parse result or the refusal; for each sound one and for the
// generic face, the fitted face, every cloned morph and, for a set of
// FaceParams, the reconstructed skin (positions, uvs, normals) and the draw
// values of avatar/render (head and eye matrices).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <span>

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "engine_golden_packages.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/expressions.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/file_io.hpp"
#include "fw/model/head_back.hpp"
#include "fw/model/mesh.hpp"
#include "fw/model/unit_morphs.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/camera.hpp"

namespace {

using nlohmann::json;
namespace model = fw::model;
namespace codec = fw::codec;

// Floats become JSON doubles exactly (every float is a double).
template <typename T>
json flat(std::span<const T> v) {
  const auto* f = reinterpret_cast<const float*>(v.data());
  return json(std::vector<float>(f, f + v.size() * sizeof(T) / sizeof(float)));
}
template <typename T>
json flat(const std::vector<T>& v) { return flat(std::span<const T>(v)); }

// The rest normals the renderer uploads (welded across texture seams).
json mesh_json(const model::Mesh& m) {
  return {{"positions", flat(m.positions)}, {"uvs", flat(m.uvs)}, {"normals", flat(model::welded_vertex_normals(m))}};
}

// The head shell's, with the normals its photo's light is taken to have been
// seen under (head_back.hpp).
json head_mesh_json(const model::Mesh& m) {
  json j = mesh_json(m);
  j["photo_light_normals"] = flat(model::photo_light_normals(m, model::welded_vertex_normals(m)));
  return j;
}

json face_params_json(const codec::FaceParams& p) {
  return {{"au", p.au}, {"head_yaw_rad", p.head_yaw_rad}, {"head_pitch_rad", p.head_pitch_rad},
          {"head_roll_rad", p.head_roll_rad}, {"head_translation_mm", p.head_translation_mm},
          {"eye_left", {{"yaw_rad", p.eye_left.yaw_rad}, {"pitch_rad", p.eye_left.pitch_rad}}},
          {"eye_right", {{"yaw_rad", p.eye_right.yaw_rad}, {"pitch_rad", p.eye_right.pitch_rad}}},
          {"lid_left", p.lid_left}, {"lid_right", p.lid_right}, {"blush", p.blush}, {"pallor", p.pallor},
          {"corrective", p.corrective}};
}

// Neutral, an expression, everything at once, and values out of range
// (reconstruction clamps them).
std::vector<std::pair<std::string, codec::FaceParams>> frames() {
  std::vector<std::pair<std::string, codec::FaceParams>> out;
  out.emplace_back("neutral", codec::FaceParams{});
  codec::FaceParams joy;
  model::apply_expression(model::Expression::joy, 0.8f, joy);
  joy.head_yaw_rad = 0.3f;
  joy.eye_left = {0.2f, -0.1f};
  joy.eye_right = {0.25f, -0.1f};
  out.emplace_back("joy", joy);
  codec::FaceParams all;
  for (std::size_t c = 0; c < all.au.size(); ++c) all.au[c] = 0.1f + 0.03f * static_cast<float>(c);
  all.head_yaw_rad = -0.7f, all.head_pitch_rad = 0.3f, all.head_roll_rad = -0.2f;
  all.head_translation_mm = {12.5f, -8.0f, 30.0f};
  all.eye_left = {-0.4f, 0.3f}, all.eye_right = {-0.35f, 0.3f};
  all.lid_left = 0.6f, all.lid_right = 1.0f;
  all.blush = {0.2f, 0.9f, 0.8f, 0.1f, 0.5f};
  all.pallor = 0.3f;
  all.corrective = {0.5f, -0.25f, 0.125f, -0.5f, 0.0625f, -0.0625f};  // the last six floats of the hand-over
  out.emplace_back("everything", all);
  codec::FaceParams over;
  over.au.fill(1.4f);
  over.au[3] = -0.5f;
  over.lid_left = 1.5f, over.lid_right = -0.2f;
  out.emplace_back("out_of_range", over);
  return out;
}

json draw_json(const model::AvatarModel& avatar, const codec::FaceParams& params) {
  const fw::render::FaceDraw draw = fw::render::face_draw(0, params);
  json eyes = json::array();
  for (std::size_t side = 0; side < 2; ++side) {
    const glm::vec2 yp = draw.eye_yaw_pitch_rad[side];
    const glm::mat4 m = draw.model * fw::render::eye_transform(avatar.face.eyes[side].centre, yp.x, yp.y);
    eyes.push_back(flat(std::span<const float>(glm::value_ptr(m), 16)));
  }
  return {{"model", flat(std::span<const float>(glm::value_ptr(draw.model), 16))}, {"eye_models", eyes}};
}

json avatar_json(const model::AvatarModel& avatar) {
  const model::GenericFace& face = avatar.face;
  json morphs = json::array();
  for (const model::Morph& m : avatar.morphs)
    morphs.push_back({{"vertex_delta", flat(m.vertex_delta)}, {"uv_delta", flat(m.uv_delta)}});
  json shapes = json::array();
  for (const auto& [name, params] : frames()) {
    model::FaceShape shape = model::reconstruct_face(avatar, params);
    model::Mesh skin{shape.positions, shape.uvs, face.skin.triangles};
    shapes.push_back({{"name", name}, {"params", face_params_json(params)}, {"positions", flat(shape.positions)},
                      {"uvs", flat(shape.uvs)}, {"normals", flat(model::vertex_normals(skin))},
                      {"draw", draw_json(avatar, params)}});
  }
  json eyes = json::array();
  for (const model::EyeLayer& eye : face.eyes)
    eyes.push_back({{"centre", flat(std::span<const glm::vec3>(&eye.centre, 1))}, {"radius", eye.radius},
                    {"cap_angle_rad", eye.cap_angle_rad}, {"mesh", mesh_json(eye.mesh)}});
  return {{"skin", mesh_json(face.skin)},
          {"eyes", eyes},
          {"mouth_cavity", mesh_json(face.mouth_cavity)},
          {"head", {{"centre", {face.head.centre.x, face.head.centre.y}}, {"outline", face.head.outline},
                    {"mesh", head_mesh_json(face.head.mesh)}}},
          {"morphs", morphs},
          {"frames", shapes}};
}

// Redefined units as the wire carries them (PROTOCOL.md 5.17): AU 1's left
// side lifting the upper face, AU 12's left side dragging the lower face
// down and forward.
codec::UnitMorphs redefined_units() {
  const model::GenericFace& generic = model::generic_face();
  const auto morph = [&](bool upper, glm::vec3 delta) {
    model::Morph m;
    m.vertex_delta.assign(generic.skin.positions.size(), glm::vec3(0.0f));
    m.uv_delta.assign(m.vertex_delta.size(), glm::vec2(0.0f));
    for (std::size_t v = 0; v < m.vertex_delta.size(); ++v)
      if ((generic.skin.positions[v].y > 0.2f) == upper && std::abs(generic.skin.positions[v].y) > 0.2f)
        m.vertex_delta[v] = delta * (0.5f + 0.5f * std::abs(generic.skin.positions[v].x));
    return m;
  };
  codec::UnitMorphs message;
  message.avatar = 1;
  message.version = 1;
  const auto au1 = static_cast<std::size_t>(codec::au_channel(1, codec::AuSide::left));
  const auto au12 = static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left));
  message.units.push_back(model::unit_morph_message(au1, morph(true, {0.0f, 0.15f, 0.02f})));
  message.units.push_back(model::unit_morph_message(au12, morph(false, {0.03f, -0.2f, 0.05f})));
  return message;
}

json units_json(const codec::UnitMorphs& message) {
  json units = json::array();
  for (const codec::UnitMorphs::Unit& unit : message.units) {
    json moves = json::array();
    for (const codec::UnitMorphs::Move& move : unit.moves)
      moves.push_back({{"vertex", move.vertex}, {"delta", {move.delta[0], move.delta[1], move.delta[2]}}});
    units.push_back({{"channel", unit.channel}, {"moves", moves}});
  }
  return units;
}

// An avatar with the redefined units: the units as the engine is handed them
// and the frames the C++ reconstructs with them.
json redefined_json(model::AvatarModel avatar) {
  const codec::UnitMorphs message = redefined_units();
  std::string error;
  const auto set = model::unit_morph_set(message, model::generic_face().skin.positions.size(), error);
  if (!set) throw std::runtime_error(error);
  model::set_unit_morphs(avatar, model::generic_face(), *set);
  json frames_json = json::array();
  for (const auto& [name, params] : frames()) {
    const model::FaceShape shape = model::reconstruct_face(avatar, params);
    frames_json.push_back({{"name", name}, {"positions", flat(shape.positions)}, {"uvs", flat(shape.uvs)}});
  }
  return {{"units", units_json(message)}, {"frames", frames_json}};
}

json package_json(const model::AvatarPackage& p) {
  const auto image = [](const model::PackageImage& i) {
    return i.bytes.empty() ? json(nullptr) : json{{"type", i.type}, {"size", i.bytes.size()}};
  };
  return {{"version", p.version}, {"generic_face_version", p.generic_face_version},
          {"skin_tone", p.skin_tone}, {"iris_colour", p.iris_colour},
          {"texture_light", p.texture_light == model::TextureLight::albedo ? "albedo" : "photo"},
          {"closed_lid_rect", flat(std::span<const glm::vec4>(&p.closed_lid_rect, 1))},
          {"head_outline", p.head_outline}, {"fitted_vertices", flat(p.fitted_vertices)},
          {"landmarks", flat(std::span<const glm::vec2>(p.landmarks))},
          {"images", {{"faceTexture", image(p.face_texture)}, {"closedLid", image(p.closed_lid)},
                      {"eye", image(p.eye)}, {"mouth", image(p.mouth)},
                      {"colourMasksA", image(p.colour_masks_a)}, {"colourMasksB", image(p.colour_masks_b)},
                      {"preview", image(p.preview)}}}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: write_engine_goldens SEED.fwa OUT_DIR\n";
    return 2;
  }
  std::vector<std::uint8_t> seed;
  std::string error;
  if (!model::read_file(argv[1], model::kMaxPackageBytes, seed, error)) {
    std::cerr << error << "\n";
    return 2;
  }
  const std::filesystem::path out_dir = argv[2];
  std::filesystem::create_directories(out_dir);
  json goldens = {{"generic_face_version", model::kGenericFaceVersion},
                  {"generic", avatar_json(model::generic_avatar_model())},
                  {"generic_redefined", redefined_json(model::generic_avatar_model())},
                  {"packages", json::array()}};
  try {
    for (const fw::test::GoldenPackage& g : fw::test::golden_packages(seed)) {
      if (!model::write_file_atomically(out_dir / (g.name + ".fwa"), g.bytes, error)) throw std::runtime_error(error);
      json entry = {{"name", g.name}, {"file", g.name + ".fwa"}, {"sound", g.sound}};
      if (g.sound) {
        model::AvatarPackage package;
        if (!model::parse_avatar_package(g.bytes, package, error)) throw std::runtime_error(g.name + ": " + error);
        entry["package"] = package_json(package);
        const model::AvatarModel avatar =
            model::make_avatar_model(model::generic_face(), package.fitted_vertices, package.head_outline);
        entry["avatar"] = avatar_json(avatar);
        entry["redefined"] = redefined_json(avatar);
      } else {
        entry["error"] = g.error;
        entry["refusal"] = g.refusal;
      }
      goldens["packages"].push_back(entry);
    }
  } catch (const std::exception& e) {
    std::cerr << "write_engine_goldens: " << e.what() << "\n";
    return 1;
  }
  const std::string text = goldens.dump();
  if (!model::write_file_atomically(out_dir / "goldens.json", {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, error)) {
    std::cerr << error << "\n";
    return 1;
  }
  return 0;
}
