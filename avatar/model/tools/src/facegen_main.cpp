// facewire-facegen: writes the generic face asset. Run by `make facegen`
// after a change to the generator; the test suite checks that the committed
// asset matches what this produces.
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>

#include "fw/facegen/generate_generic_face.hpp"
#include "fw/model/face_asset.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Generate the facewire generic face asset"};
  std::string output = "generic_face.json";
  app.add_option("-o,--output", output, "where to write the asset");
  CLI11_PARSE(app, argc, argv);

  const fw::model::GenericFace face = fw::facegen::generate_generic_face();
  const auto problems = fw::model::validate_generic_face(face);
  for (const auto& problem : problems) std::cerr << "facewire-facegen: " << problem << "\n";
  if (!problems.empty()) return 1;

  std::ofstream out(output, std::ios::binary);
  out << fw::model::serialize_face_asset(face);
  if (!out) {
    std::cerr << "facewire-facegen: cannot write " << output << "\n";
    return 1;
  }
  std::cout << "wrote " << output << ": " << face.skin.positions.size() << " vertices, "
            << face.skin.triangles.size() << " triangles\n";
  return 0;
}
