#include <cstdio>
#include <sstream>

#include "fw/model/face_asset.hpp"

namespace fw::model {
namespace {

// Six significant digits are well below a texel and a tenth of a millimetre,
// and keep the committed file small and its diffs readable.
std::string number(float v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", static_cast<double>(v));
  std::string s(buffer);
  return s == "-0" ? "0" : s;
}

template <typename Item, typename Write>
void write_rows(std::ostringstream& out, const std::vector<Item>& items, Write write_item,
                const char* indent) {
  out << "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out << (i == 0 ? "\n" : ",\n") << indent;
    write_item(items[i]);
  }
  out << "]";
}

void write_mesh(std::ostringstream& out, const Mesh& mesh, const char* indent) {
  const std::string inner = std::string(indent) + "  ";
  out << "{\n" << inner << "\"positions\": ";
  write_rows(out, mesh.positions, [&](const glm::vec3& p) {
    out << "[" << number(p.x) << ", " << number(p.y) << ", " << number(p.z) << "]";
  }, (inner + "  ").c_str());
  out << ",\n" << inner << "\"uvs\": ";
  write_rows(out, mesh.uvs, [&](const glm::vec2& t) {
    out << "[" << number(t.x) << ", " << number(t.y) << "]";
  }, (inner + "  ").c_str());
  out << ",\n" << inner << "\"triangles\": ";
  write_rows(out, mesh.triangles, [&](const glm::uvec3& t) {
    out << "[" << t.x << ", " << t.y << ", " << t.z << "]";
  }, (inner + "  ").c_str());
  out << "\n" << indent << "}";
}

template <typename Container>
void write_index_list(std::ostringstream& out, const Container& values) {
  out << "[";
  bool first = true;
  for (const auto v : values) {
    out << (first ? "" : ", ") << v;
    first = false;
  }
  out << "]";
}

}  // namespace

std::string serialize_face_asset(const GenericFace& face) {
  std::ostringstream out;
  out << "{\n  \"format\": \"facewire-generic-face\",\n  \"version\": " << face.version << ",\n";
  out << "  \"units\": \"inter-ocular distance; x right, y up, z toward the viewer\",\n";
  out << "  \"texture_frame\": {\"origin\": [" << number(face.texture_frame.origin.x) << ", "
      << number(face.texture_frame.origin.y) << "], \"size\": " << number(face.texture_frame.size)
      << "},\n";
  out << "  \"regions\": [";
  for (std::size_t i = 0; i < kFaceRegionNames.size(); ++i)
    out << (i ? ", " : "") << "\"" << kFaceRegionNames[i] << "\"";
  out << "],\n  \"landmark_vertices\": ";
  write_index_list(out, face.landmark_vertices);
  out << ",\n  \"holes\": {\"eye_right\": ";
  write_index_list(out, face.eye_holes[0]);
  out << ", \"eye_left\": ";
  write_index_list(out, face.eye_holes[1]);
  out << ", \"mouth\": ";
  write_index_list(out, face.mouth_slit);
  out << "},\n  \"skin\": ";
  write_mesh(out, face.skin, "  ");
  out << ",\n  \"triangle_regions\": [";
  for (std::size_t i = 0; i < face.triangle_regions.size(); ++i)
    out << (i ? (i % 32 == 0 ? ",\n    " : ", ") : "\n    ") << static_cast<int>(face.triangle_regions[i]);
  out << "\n  ],\n  \"eyes\": {";
  for (int side = 0; side < 2; ++side) {
    const EyeLayer& eye = face.eyes[static_cast<std::size_t>(side)];
    out << (side ? ",\n" : "\n") << "    \"" << (side ? "left" : "right") << "\": {\"centre\": ["
        << number(eye.centre.x) << ", " << number(eye.centre.y) << ", " << number(eye.centre.z)
        << "], \"radius\": " << number(eye.radius) << ", \"cap_angle_rad\": "
        << number(eye.cap_angle_rad) << ",\n      \"mesh\": ";
    write_mesh(out, eye.mesh, "      ");
    out << "}";
  }
  out << "\n  },\n  \"mouth_cavity\": ";
  write_mesh(out, face.mouth_cavity, "  ");
  out << ",\n  \"head\": {\"centre\": [" << number(face.head.centre.x) << ", " << number(face.head.centre.y)
      << "],\n    \"outline\": [";
  for (std::size_t i = 0; i < face.head.outline.size(); ++i) out << (i ? ", " : "") << number(face.head.outline[i]);
  out << "],\n    \"mesh\": ";
  write_mesh(out, face.head.mesh, "    ");
  out << "}";
  // Action units: only the vertices a unit moves, as [vertex, dx, dy, dz, du, dv].
  out << ",\n  \"action_units\": [";
  for (std::size_t c = 0; c < face.action_units.size(); ++c) {
    const codec::AuChannel channel = codec::kAuChannels[c];
    const Morph& morph = face.action_units[c];
    const char* side = channel.side == codec::AuSide::left ? "left" : channel.side == codec::AuSide::right ? "right" : "both";
    out << (c ? ",\n" : "\n") << "    {\"au\": " << static_cast<int>(channel.au) << ", \"side\": \"" << side
        << "\", \"moves\": [";
    bool first = true;
    for (std::size_t v = 0; v < morph.vertex_delta.size(); ++v) {
      const glm::vec3 d = morph.vertex_delta[v];
      const glm::vec2 t = morph.uv_delta[v];
      if (d == glm::vec3(0.0f) && t == glm::vec2(0.0f)) continue;
      out << (first ? "\n      [" : ",\n      [") << v << ", " << number(d.x) << ", " << number(d.y) << ", "
          << number(d.z) << ", " << number(t.x) << ", " << number(t.y) << "]";
      first = false;
    }
    out << "]}";
  }
  // Corrective components: only the vertices each moves, as [vertex, dx, dy, dz].
  out << "\n  ],\n  \"correctives\": [";
  for (std::size_t k = 0; k < face.correctives.size(); ++k) {
    out << (k ? ",\n" : "\n") << "    {\"component\": " << k << ", \"moves\": [";
    bool first = true;
    const std::vector<glm::vec3>& delta = face.correctives[k].vertex_delta;
    for (std::size_t v = 0; v < delta.size(); ++v) {
      if (delta[v] == glm::vec3(0.0f)) continue;
      out << (first ? "\n      [" : ",\n      [") << v << ", " << number(delta[v].x) << ", " << number(delta[v].y)
          << ", " << number(delta[v].z) << "]";
      first = false;
    }
    out << "]}";
  }
  out << (face.correctives.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return out.str();
}

}  // namespace fw::model
