#include <stdexcept>

#include <nlohmann/json.hpp>

#include "fw/model/face_asset.hpp"

namespace fw::model {
namespace {

using nlohmann::json;

// Thrown inside the parser only; parse_face_asset turns it into its error text.
struct AssetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const json& member(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw AssetError(where + ": missing \"" + key + "\"");
  return object.at(key);
}

float read_float(const json& value, const std::string& where) {
  if (!value.is_number()) throw AssetError(where + ": expected a number");
  return value.get<float>();
}

std::uint32_t read_index(const json& value, const std::string& where) {
  if (!value.is_number_unsigned()) throw AssetError(where + ": expected a non-negative integer");
  return value.get<std::uint32_t>();
}

template <int N>
glm::vec<N, float> read_vec(const json& value, const std::string& where) {
  if (!value.is_array() || value.size() != N)
    throw AssetError(where + ": expected " + std::to_string(N) + " numbers");
  glm::vec<N, float> v;
  for (int i = 0; i < N; ++i) v[i] = read_float(value[static_cast<std::size_t>(i)], where);
  return v;
}

const json& read_array(const json& object, const char* key, const std::string& where) {
  const json& value = member(object, key, where);
  if (!value.is_array()) throw AssetError(where + "." + key + ": expected an array");
  return value;
}

std::vector<std::uint32_t> read_index_list(const json& value, const std::string& where) {
  if (!value.is_array()) throw AssetError(where + ": expected an array of indices");
  std::vector<std::uint32_t> list;
  for (const json& item : value) list.push_back(read_index(item, where));
  return list;
}

Mesh read_mesh(const json& object, const std::string& where) {
  Mesh mesh;
  for (const json& p : read_array(object, "positions", where))
    mesh.positions.push_back(read_vec<3>(p, where + ".positions"));
  for (const json& t : read_array(object, "uvs", where)) mesh.uvs.push_back(read_vec<2>(t, where + ".uvs"));
  for (const json& t : read_array(object, "triangles", where)) {
    const std::vector<std::uint32_t> i = read_index_list(t, where + ".triangles");
    if (i.size() != 3) throw AssetError(where + ".triangles: expected 3 indices per triangle");
    mesh.triangles.emplace_back(i[0], i[1], i[2]);
  }
  return mesh;
}

EyeLayer read_eye(const json& object, const std::string& where) {
  EyeLayer eye;
  eye.centre = read_vec<3>(member(object, "centre", where), where + ".centre");
  eye.radius = read_float(member(object, "radius", where), where + ".radius");
  eye.cap_angle_rad = read_float(member(object, "cap_angle_rad", where), where + ".cap_angle_rad");
  eye.mesh = read_mesh(member(object, "mesh", where), where + ".mesh");
  return eye;
}

// Action units come in FaceParams channel order, each naming its AU and side
// so that a reordered file is caught.
void read_action_units(const json& units, GenericFace& face) {
  if (units.size() != codec::kAuChannelCount)
    throw AssetError("asset.action_units: expected " + std::to_string(codec::kAuChannelCount) + " units, found " +
                     std::to_string(units.size()));
  const std::size_t vertex_count = face.skin.positions.size();
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const json& unit = units[c];
    const std::string where = "action_units[" + std::to_string(c) + "]";
    const codec::AuChannel expected = codec::kAuChannels[c];
    const std::string side = member(unit, "side", where).get<std::string>();
    const auto expected_side = expected.side == codec::AuSide::left ? "left" : expected.side == codec::AuSide::right ? "right" : "both";
    if (member(unit, "au", where).get<int>() != expected.au || side != expected_side)
      throw AssetError(where + ": expected AU " + std::to_string(expected.au) + " " + expected_side);
    Morph& morph = face.action_units[c];
    morph.vertex_delta.assign(vertex_count, glm::vec3(0.0f));
    morph.uv_delta.assign(vertex_count, glm::vec2(0.0f));
    for (const json& move : read_array(unit, "moves", where)) {
      if (!move.is_array() || move.size() != 6) throw AssetError(where + ".moves: expected [vertex, dx, dy, dz, du, dv]");
      const std::uint32_t v = read_index(move[0], where);
      if (v >= vertex_count) throw AssetError(where + ".moves: vertex index out of range");
      morph.vertex_delta[v] = {read_float(move[1], where), read_float(move[2], where), read_float(move[3], where)};
      morph.uv_delta[v] = {read_float(move[4], where), read_float(move[5], where)};
    }
  }
}

// Corrective components in order, each naming its index; a vertex field
// only (the physics residual moves skin, it slides no texture).
void read_correctives(const json& components, GenericFace& face) {
  if (components.size() > codec::kCorrectiveCount)
    throw AssetError("asset.correctives: at most " + std::to_string(codec::kCorrectiveCount) + " components, found " +
                     std::to_string(components.size()));
  const std::size_t vertex_count = face.skin.positions.size();
  face.correctives.assign(components.size(), Morph{});
  for (std::size_t k = 0; k < components.size(); ++k) {
    const std::string where = "correctives[" + std::to_string(k) + "]";
    const json& index = member(components[k], "component", where);
    if (!index.is_number_unsigned() || index.get<std::size_t>() != k)
      throw AssetError(where + ": expected component " + std::to_string(k));
    Morph& morph = face.correctives[k];
    morph.vertex_delta.assign(vertex_count, glm::vec3(0.0f));
    for (const json& move : read_array(components[k], "moves", where)) {
      if (!move.is_array() || move.size() != 4) throw AssetError(where + ".moves: expected [vertex, dx, dy, dz]");
      const std::uint32_t v = read_index(move[0], where);
      if (v >= vertex_count) throw AssetError(where + ".moves: vertex index out of range");
      morph.vertex_delta[v] = {read_float(move[1], where), read_float(move[2], where), read_float(move[3], where)};
    }
  }
}

GenericFace read_face(const json& root) {
  GenericFace face;
  if (member(root, "format", "asset") != "facewire-generic-face")
    throw AssetError("asset: \"format\" is not facewire-generic-face");
  const json& version = member(root, "version", "asset");
  if (!version.is_number_integer() || version.get<int>() != kGenericFaceVersion)
    throw AssetError("asset: version " + version.dump() + " is not supported (this build reads version " +
                     std::to_string(kGenericFaceVersion) + ")");

  const json& frame = member(root, "texture_frame", "asset");
  face.texture_frame.origin = read_vec<2>(member(frame, "origin", "texture_frame"), "texture_frame.origin");
  face.texture_frame.size = read_float(member(frame, "size", "texture_frame"), "texture_frame.size");

  // Region ids in the file index the file's own name list, so a renamed or
  // reordered region is caught here rather than silently mislabelled.
  std::vector<FaceRegion> region_of_id;
  for (const json& name : read_array(root, "regions", "asset")) {
    const auto region = name.is_string() ? face_region_from_name(name.get<std::string>()) : std::nullopt;
    if (!region) throw AssetError("asset.regions: unknown region " + name.dump());
    region_of_id.push_back(*region);
  }

  const std::vector<std::uint32_t> anchors =
      read_index_list(member(root, "landmark_vertices", "asset"), "landmark_vertices");
  if (anchors.size() != face.landmark_vertices.size())
    throw AssetError("asset.landmark_vertices: expected 68 indices, found " + std::to_string(anchors.size()));
  std::copy(anchors.begin(), anchors.end(), face.landmark_vertices.begin());

  const json& holes = member(root, "holes", "asset");
  face.eye_holes[0] = read_index_list(member(holes, "eye_right", "holes"), "holes.eye_right");
  face.eye_holes[1] = read_index_list(member(holes, "eye_left", "holes"), "holes.eye_left");
  face.mouth_slit = read_index_list(member(holes, "mouth", "holes"), "holes.mouth");

  face.skin = read_mesh(member(root, "skin", "asset"), "skin");
  for (const json& id : read_array(root, "triangle_regions", "asset")) {
    const std::uint32_t i = read_index(id, "triangle_regions");
    if (i >= region_of_id.size()) throw AssetError("asset.triangle_regions: region id out of range");
    face.triangle_regions.push_back(region_of_id[i]);
  }
  const json& eyes = member(root, "eyes", "asset");
  face.eyes[0] = read_eye(member(eyes, "right", "eyes"), "eyes.right");
  face.eyes[1] = read_eye(member(eyes, "left", "eyes"), "eyes.left");
  face.mouth_cavity = read_mesh(member(root, "mouth_cavity", "asset"), "mouth_cavity");
  const json& head = member(root, "head", "asset");
  face.head.centre = read_vec<2>(member(head, "centre", "head"), "head.centre");
  for (const json& r : read_array(head, "outline", "head")) face.head.outline.push_back(read_float(r, "head.outline"));
  face.head.mesh = read_mesh(member(head, "mesh", "head"), "head.mesh");
  read_action_units(read_array(root, "action_units", "asset"), face);
  read_correctives(read_array(root, "correctives", "asset"), face);
  return face;
}

}  // namespace

bool parse_face_asset(std::string_view text, GenericFace& face, std::string& error) {
  const json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded()) {
    error = "the generic face asset is not valid JSON";
    return false;
  }
  GenericFace parsed;
  try {
    parsed = read_face(root);
  } catch (const AssetError& e) {
    error = std::string("the generic face asset is malformed: ") + e.what();
    return false;
  } catch (const json::exception& e) {
    error = std::string("the generic face asset is malformed: ") + e.what();
    return false;
  }
  const std::vector<std::string> problems = validate_generic_face(parsed);
  if (!problems.empty()) {
    error = "the generic face asset is unsound: " + problems.front() +
            (problems.size() > 1 ? " (and " + std::to_string(problems.size() - 1) + " more)" : "");
    return false;
  }
  face = std::move(parsed);
  return true;
}

}  // namespace fw::model
