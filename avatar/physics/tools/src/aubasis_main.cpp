// facewire-aubasis: the generic face's action units synthesised by the
// physics face. Reads a face asset (the output of facewire-facegen), replaces
// each unit's vertex field by the settled displacement of the simulated face
// with that unit alone at intensity 1 (the texture slides stay), validates
// and writes it. `make facegen` runs facegen then this; tests/physics checks
// that the committed asset is what this makes.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>

#include "fw/model/face_asset.hpp"
#include "fw/model/file_io.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/tissue_model.hpp"
#include "fw/physics/synthesize_action_units.hpp"

namespace {

constexpr std::size_t kMaxAssetBytes = 64u << 20;

const char* side_name(fw::codec::AuSide side) {
  switch (side) {
    case fw::codec::AuSide::left: return "L";
    case fw::codec::AuSide::right: return "R";
    default: return " ";
  }
}

// How the physics units compare with the ones they replace: peak motion and
// the cosine between the two fields (1 = the same shape).
void report(const fw::model::GenericFace& before, const fw::model::GenericFace& after) {
  std::printf("AU side  input_peak_mm  physics_peak_mm  ratio  cosine\n");
  for (std::size_t c = 0; c < fw::codec::kAuChannelCount; ++c) {
    const auto& a = before.action_units[c].vertex_delta;
    const auto& b = after.action_units[c].vertex_delta;
    double peak_a = 0, peak_b = 0, ab = 0, aa = 0, bb = 0;
    for (std::size_t v = 0; v < b.size(); ++v) {
      const glm::vec3 va = v < a.size() ? a[v] : glm::vec3(0.0f);
      peak_a = std::max(peak_a, double(glm::length(va)));
      peak_b = std::max(peak_b, double(glm::length(b[v])));
      ab += glm::dot(va, b[v]);
      aa += glm::dot(va, va);
      bb += glm::dot(b[v], b[v]);
    }
    const double mm = fw::model::kMillimetresPerUnit;
    std::printf("%2d  %s    %8.2f       %8.2f       %5.2f  %5.2f\n", fw::codec::kAuChannels[c].au,
                side_name(fw::codec::kAuChannels[c].side), peak_a * mm, peak_b * mm,
                peak_a > 0 ? peak_b / peak_a : 0.0, aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0);
  }
}

void print_muscle_table(const fw::model::GenericFace& face) {
  const auto tissue = fw::physics::build_tissue_model(face, face.action_units);
  std::printf("muscle                                 nodes  weight  origin (x, y, z)\n");
  for (std::size_t i = 0; i < tissue->muscles.size(); ++i) {
    const auto& m = tissue->muscles[i];
    float weight = 0;
    for (std::uint32_t t = m.first; t < m.last; ++t) weight += tissue->attach_weight[t];
    std::printf("%-38s %5u  %6.2f  (%.3f, %.3f, %.3f)\n", fw::physics::muscle_name(i).c_str(), m.last - m.first,
                weight, m.origin.x, m.origin.y, m.origin.z);
  }
  std::printf("nodes %u, springs %zu, elements %zu, stable mass-spring sub-step %.5f s\n", tissue->node_count,
              tissue->spring_count(), tissue->element_count(), tissue->stable_substep_s);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Replace the generic face's action-unit vertex fields by physics-synthesised ones"};
  std::string input, output;
  bool print_report = false, print_muscles = false;
  unsigned threads = 0;
  app.add_option("-i,--input", input, "face asset to read (facewire-facegen's output)")->required();
  app.add_option("-o,--output", output, "where to write the asset (may be the input)")->required();
  app.add_flag("--report", print_report, "print how each unit compares with the input's");
  app.add_flag("--muscles", print_muscles, "print each muscle's attachments on the input face");
  app.add_option("--threads", threads, "threads (0 = one per hardware thread)");
  CLI11_PARSE(app, argc, argv);

  std::vector<std::uint8_t> bytes;
  std::string error;
  if (!fw::model::read_file(input, kMaxAssetBytes, bytes, error)) {
    std::cerr << "facewire-aubasis: " << error << "\n";
    return 1;
  }
  fw::model::GenericFace face;
  if (!fw::model::parse_face_asset(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), face,
                                   error)) {
    std::cerr << "facewire-aubasis: " << input << " is not a valid face asset: " << error
              << "; regenerate it with facewire-facegen\n";
    return 1;
  }
  if (print_muscles) print_muscle_table(face);
  const fw::model::GenericFace before = face;
  fw::physics::FacePool pool(threads);
  fw::physics::replace_action_unit_displacements(face, fw::physics::synthesize_action_units(face, {}, &pool));
  const auto problems = fw::model::validate_generic_face(face);
  for (const auto& problem : problems) std::cerr << "facewire-aubasis: " << problem << "\n";
  if (!problems.empty()) return 1;
  if (print_report) report(before, face);

  const std::string text = fw::model::serialize_face_asset(face);
  if (!fw::model::write_file_atomically(output, text, error)) {
    std::cerr << "facewire-aubasis: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << output << ": " << fw::codec::kAuChannelCount << " physics-synthesised action units\n";
  return 0;
}
