// facewire-correctives: the generic face's corrective basis. Reads a face
// asset (facewire-aubasis's output: its action units the physics face's),
// simulates the fitting part of the behaviour corpus (avatar/physics/corpus)
// as rooms do, fits the principal components of what the action units leave
// (corrective_fit.hpp), writes them into the asset as `correctives`, and
// reports what they cut on the held-out part. `make facegen` runs it after
// facewire-aubasis; the output depends only on its inputs.
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "fw/model/face_asset.hpp"
#include "fw/model/file_io.hpp"
#include "fw/physics/corrective_fit.hpp"
#include "fw/physics/face_pool.hpp"

namespace {

constexpr std::size_t kMaxAssetBytes = 64u << 20;

bool load_corpus(const std::string& path, fw::physics::BehaviourCorpus& corpus) {
  std::string error;
  if (fw::physics::load_behaviour_corpus(path, corpus, error)) return true;
  std::cerr << "facewire-correctives: " << error << "\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the physics face's corrective basis and write it into the face asset"};
  std::string input, output, fitting, held_out;
  std::size_t count = fw::codec::kCorrectiveCount;
  unsigned threads = 0;
  app.add_option("-i,--input", input, "face asset to read (facewire-aubasis's output)")->required();
  app.add_option("-o,--output", output, "where to write the asset (may be the input)")->required();
  app.add_option("--fitting", fitting, "the corpus to fit on")->required();
  app.add_option("--held-out", held_out, "a corpus to report the fit on (not fitted)");
  app.add_option("--count", count, "components, at most 6")->check(CLI::Range(std::size_t{0}, fw::codec::kCorrectiveCount))
      ->capture_default_str();
  app.add_option("--threads", threads, "threads (0 = one per hardware thread)");
  CLI11_PARSE(app, argc, argv);

  std::vector<std::uint8_t> bytes;
  std::string error;
  fw::model::GenericFace face;
  if (!fw::model::read_file(input, kMaxAssetBytes, bytes, error) ||
      !fw::model::parse_face_asset(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), face,
                                   error)) {
    std::cerr << "facewire-correctives: " << input << ": " << error
              << "; regenerate it with facewire-facegen and facewire-aubasis\n";
    return 1;
  }
  fw::physics::BehaviourCorpus fit_corpus, held_corpus;
  if (!load_corpus(fitting, fit_corpus) || (!held_out.empty() && !load_corpus(held_out, held_corpus))) return 1;

  fw::physics::FacePool pool(threads);
  face.correctives.clear();  // the residual is taken against the action units alone
  const auto recording = fw::physics::record_corpus(face, fit_corpus, fw::physics::Solver::projective, &pool);
  face.correctives = fw::physics::fit_correctives(face, recording, count);
  const auto problems = fw::model::validate_generic_face(face);
  for (const auto& problem : problems) std::cerr << "facewire-correctives: " << problem << "\n";
  if (!problems.empty()) return 1;

  const auto report = [&](const char* part, const fw::physics::BehaviourCorpus& corpus, std::uint64_t people) {
    const auto errors = fw::physics::corrective_errors(
        face, fw::physics::record_corpus(face, corpus, fw::physics::Solver::projective, &pool, people));
    std::printf("%s: %zu frames, residual %.3f mm RMS without the correctives, %.3f mm with (%.3f of it)\n", part,
                corpus.frame_count(), errors.without_mm, errors.with_mm, errors.cut());
  };
  report("fitting", fit_corpus, fw::physics::kFittingFirstSeed);
  if (!held_out.empty()) report("held out (other people)", held_corpus, fw::physics::kHeldOutFirstSeed);

  const std::string text = fw::model::serialize_face_asset(face);
  if (!fw::model::write_file_atomically(output, text, error)) {
    std::cerr << "facewire-correctives: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << output << ": " << face.correctives.size() << " corrective components\n";
  return 0;
}
