// codec_make_vectors DIR: (re)writes the codec's golden vectors into DIR
// (tests/vectors/codec): for each vector <name>.fwc (the messages),
// <name>.fwscene (the faces encoded) and <name>.json (options, ticks,
// errors, expected values), plus errors.json. Deterministic: running it
// again must leave the files unchanged (vectors_test checks that the
// committed ones still match). A change to any vector is a change of format
// version (codec/FORMAT.md, "Golden vectors").
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "golden_vectors.hpp"
#include "fw/behavior/scene_file.hpp"

namespace {

bool write_file(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fw::codec::vectors;
  if (argc != 2) {
    std::cerr << "usage: codec_make_vectors DIR   (normally tests/vectors/codec)\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (const VectorSpec& spec : vector_specs()) {
    const auto messages = encode_vector(spec);
    const auto decoded = decode_vector(spec, messages);
    const auto stream = to_stream_file(messages);
    fw::behavior::Scene scene;
    scene.name = spec.name;
    for (std::size_t a = 0; a < spec.inputs.size(); ++a)
      scene.avatars.push_back({"avatar-" + std::to_string(a), false, spec.inputs[a]});
    std::string error;
    if (!write_file(dir / (spec.name + ".fwc"), std::string(stream.begin(), stream.end())) ||
        !write_file(dir / (spec.name + ".json"), to_json(spec, messages, decoded).dump(1) + "\n") ||
        !fw::behavior::write_scene(scene, (dir / (spec.name + ".fwscene")).string(), error)) {
      std::cerr << "codec_make_vectors: cannot write " << spec.name << " into " << dir << " " << error << "\n";
      return 1;
    }
    std::cout << spec.name << ": " << messages.size() << " messages, " << stream.size() << " bytes\n";
  }
  if (!write_file(dir / "errors.json", error_cases().dump(1) + "\n")) {
    std::cerr << "codec_make_vectors: cannot write errors.json into " << dir << "\n";
    return 1;
  }
  return 0;
}
