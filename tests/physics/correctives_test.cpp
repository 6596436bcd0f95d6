// The corrective basis on the physics side: what it cuts on held-out
// behaviour, the committed components against a fresh fit, measure()'s
// corrective weights, and the projection kernel.
#include "fw/physics/corrective_fit.hpp"

#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/landmark_template.hpp"
#include "fw/physics/corrective_projection.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/tissue_model.hpp"
#include "generic_tissue.hpp"
#include "test_paths.hpp"

namespace fw::physics {
namespace {

BehaviourCorpus committed_corpus(const std::string& part) {
  BehaviourCorpus corpus;
  std::string error;
  EXPECT_TRUE(load_behaviour_corpus(test::source_path("avatar/physics/corpus/" + part + ".txt"), corpus, error))
      << error;
  return corpus;
}

// The bar: on behaviour it was not fitted on, by people it was not
// fitted on, the corrective weights halve the error of the rebuilt face
// against the simulated skin.
TEST(Correctives, HalveTheErrorOnHeldOutBehaviour) {
  const model::GenericFace& face = model::generic_face();
  ASSERT_FALSE(face.correctives.empty()) << "the asset has no corrective basis: run `make facegen`";
  ASSERT_LT(kFittingFirstSeed + committed_corpus("fitting").sequences.size(), kHeldOutFirstSeed)
      << "the held-out people must be none of the fitting's";
  FacePool pool;
  const CorrectiveErrors errors = corrective_errors(
      face, record_corpus(face, committed_corpus("held_out"), Solver::projective, &pool, kHeldOutFirstSeed));
  EXPECT_GT(errors.without_mm, 0.05) << "the held-out corpus moves the face beyond what the AUs rebuild";
  EXPECT_LE(errors.cut(), 0.5) << errors.with_mm << " mm with the correctives against " << errors.without_mm
                               << " mm without";
}

// The committed components are what facewire-correctives fits now. After
// changing the tissue, the muscles, the solver or the corpus, run `make
// facegen` and commit the asset.
TEST(Correctives, TheCommittedBasisIsWhatTheFitMakesNow) {
  model::GenericFace face = model::generic_face();
  const std::vector<model::Morph> committed = face.correctives;
  face.correctives.clear();
  FacePool pool;
  const std::vector<model::Morph> fresh =
      fit_correctives(face, record_corpus(face, committed_corpus("fitting"), Solver::projective, &pool));
  ASSERT_EQ(fresh.size(), committed.size()) << "run `make facegen` and commit avatar/model/assets/generic_face.json";
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    float worst = 0;
    for (std::size_t v = 0; v < fresh[k].vertex_delta.size(); ++v)
      worst = std::max(worst, glm::length(fresh[k].vertex_delta[v] - committed[k].vertex_delta[v]));
    // The asset holds 6 significant digits, and a value near the zero
    // threshold may be written either way.
    EXPECT_LT(worst, 2e-4f) << "component " << k << " differs by " << worst * model::kMillimetresPerUnit
                            << " mm: run `make facegen` and commit avatar/model/assets/generic_face.json";
  }
}

TEST(Correctives, TheFitIsScaledToTheCorpusAndOrthogonal) {
  const auto& c = model::generic_face().correctives;
  ASSERT_EQ(c.size(), codec::kCorrectiveCount);
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = 0; j < c.size(); ++j) {
      double dot = 0, ii = 0, jj = 0;
      for (std::size_t v = 0; v < c[i].vertex_delta.size(); ++v) {
        dot += glm::dot(c[i].vertex_delta[v], c[j].vertex_delta[v]);
        ii += glm::dot(c[i].vertex_delta[v], c[i].vertex_delta[v]);
        jj += glm::dot(c[j].vertex_delta[v], c[j].vertex_delta[v]);
      }
      if (i != j) {
        EXPECT_LT(std::abs(dot) / std::sqrt(ii * jj), 0.01) << i << " " << j << ": principal components";
      }
    }
  // Weights in [-1,1] cover the fitting corpus to its 99.9th percentile:
  // at most a few per cent of its frames clamp.
  FacePool pool;
  const CorpusRecording r = record_corpus(model::generic_face(), committed_corpus("fitting"), Solver::projective, &pool);
  std::size_t clamped = 0, moving = 0;
  for (const FaceMeasurement& m : r.measured)
    for (float w : m.corrective) {
      clamped += std::abs(w) >= 1.0f ? 1 : 0;
      moving += std::abs(w) > 0.05f ? 1 : 0;
    }
  EXPECT_LT(double(clamped), 0.03 * double(r.frame_count() * codec::kCorrectiveCount));
  EXPECT_GT(moving, r.frame_count() / 4) << "the weights use their range";
}

// A face whose jaw opens measures corrective weights while it moves; at
// rest on the neutral face they are 0; a face built without the basis
// measures none.
TEST(Correctives, MeasureGivesTheWeightsWhileTheFaceMoves) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation face(model::generic_face(), options);
  EXPECT_EQ(face.measure().corrective, (std::array<float, codec::kCorrectiveCount>{}));
  AuFrame targets{};
  targets[codec::au_channel(27, codec::AuSide::both)] = 1.0f;
  targets[codec::au_channel(12, codec::AuSide::left)] = 0.7f;
  face.set_action_units(targets);
  float largest = 0;
  for (int i = 0; i < 6; ++i) {
    face.step(1.0 / 30);
    for (float w : face.measure().corrective) {
      EXPECT_LE(std::abs(w), 1.0f);
      largest = std::max(largest, std::abs(w));
    }
  }
  EXPECT_GT(largest, 0.1f);
  FaceSimulation bare(test::generic_tissue(), options);
  bare.set_action_units(targets);
  bare.step(1.0 / 30);
  EXPECT_EQ(bare.measure().corrective, (std::array<float, codec::kCorrectiveCount>{}));
}

// measure()'s cost with the corrective projection: a few microseconds more.
TEST(Correctives, MeasureStaysCheap) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation face(model::generic_face(), options);
  AuFrame targets{};
  targets[codec::au_channel(12, codec::AuSide::both)] = 0.8f;
  face.set_action_units(targets);
  face.step(1.0 / 30);
  constexpr int kRuns = 2000;
  float sink = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kRuns; ++i) sink += face.measure().corrective[0];
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / kRuns;
  std::printf("measure(): %.1f us\n", us);
  EXPECT_TRUE(std::isfinite(sink));
  EXPECT_LT(us, 200.0) << "generous: 20-30 us on a quiet core, more under sanitizers";
}

// The kernel: a displacement made of known AU and corrective weights gives
// the corrective weights back; beyond [-1,1] they clamp.
TEST(CorrectiveProjection, RecoversKnownWeightsAndClamps) {
  const model::GenericFace& face = model::generic_face();
  const TissueModel& tissue = *test::generic_tissue();
  const CorrectiveBasis basis = CorrectiveBasis::from_morphs(face.correctives, tissue.basis);
  ASSERT_EQ(basis.count, face.correctives.size());
  AuFrame w{};
  w[3] = 0.4f;
  w[20] = 0.9f;
  for (const std::array<float, 6>& c : {std::array<float, 6>{0.3f, -0.5f, 0.1f, 0.0f, 0.8f, -0.2f},
                                        std::array<float, 6>{2.0f, -3.0f, 0, 0, 0, 0}}) {
    std::vector<float> d(basis.length, 0.0f);
    for (std::size_t n = 0; n < d.size(); ++n) {
      for (std::size_t a = 0; a < codec::kAuChannelCount; ++a) d[n] += w[a] * tissue.basis.at(a, n);
      for (std::size_t k = 0; k < basis.count; ++k) d[n] += c[k] * basis.rows[k * basis.length + n];
    }
    const auto got = project_corrective(basis, d, w);
    for (std::size_t k = 0; k < basis.count; ++k) EXPECT_NEAR(got[k], std::clamp(c[k], -1.0f, 1.0f), 1e-3f) << k;
  }
}

TEST(BehaviourCorpus, RoundTripsAndRefusesWhatItCannotRead) {
  BehaviourCorpus corpus;
  corpus.sequences.push_back({"a-1", {AuFrame{}, AuFrame{}}, {HeadPose{}, HeadPose{0.25f, -0.5f, 0.125f, {}}}});
  corpus.sequences[0].frames[1][5] = 0.25f;
  corpus.sequences[0].frames[1][28] = 1.0f;
  corpus.sequences.push_back({"b_2", {AuFrame{}}, {}});
  corpus.sequences[1].frames[0][0] = 0.5f;
  const std::string text = write_behaviour_corpus(corpus);
  BehaviourCorpus read;
  std::string error;
  ASSERT_TRUE(read_behaviour_corpus(text, read, error)) << error;
  ASSERT_EQ(read.sequences.size(), 2u);
  EXPECT_EQ(read.sequences[0].frames, corpus.sequences[0].frames);
  EXPECT_EQ(read.sequences[1].frames, corpus.sequences[1].frames) << "a new sequence starts from 0";
  EXPECT_EQ(read.sequences[0].heads, corpus.sequences[0].heads);
  EXPECT_TRUE(read.sequences[1].heads.empty()) << "a sequence that names no head keeps it upright";
  EXPECT_EQ(write_behaviour_corpus(read), text);
  EXPECT_NE(text.find("5:250 28:1000 yaw:250 pitch:-500 roll:125\n"), std::string::npos) << text;

  const auto refusal = [](const std::string& bad) {
    BehaviourCorpus c;
    std::string e;
    EXPECT_FALSE(read_behaviour_corpus(bad, c, e)) << bad;
    return e;
  };
  EXPECT_EQ(refusal("3:100\n"), "corpus line 1: a frame before the first \"sequence NAME\" line");
  EXPECT_EQ(refusal("sequence x\n29:100\n"), "corpus line 2: \"29:100\": channels are 0..28, values 0..1000");
  EXPECT_EQ(refusal("sequence x\n3:1001\n"), "corpus line 2: \"3:1001\": channels are 0..28, values 0..1000");
  EXPECT_EQ(refusal("# c\nsequence x\n.\n3-100\n"),
            "corpus line 4: \"3-100\" is not channel:thousandths (or yaw:, pitch:, roll: milliradians)");
  EXPECT_EQ(refusal("sequence x\npitch:1201\n"),
            "corpus line 2: \"pitch:1201\": the head's pitch is milliradians, -1200..1200");
  EXPECT_EQ(refusal("sequence x\nyaw:0.5\n"), "corpus line 2: \"yaw:0.5\": the head's yaw is milliradians, -1200..1200");
  EXPECT_EQ(refusal("sequence bad name\n.\n"), "corpus line 1: a sequence's name is 1 to 64 letters, digits, '-' or '_'");
  EXPECT_EQ(refusal("sequence x\n.\nsequence y\n"), "corpus sequence y has no frames");
}

TEST(BehaviourCorpus, TheCommittedPartsAreSeparateAndMinutesLong) {
  const BehaviourCorpus fitting = committed_corpus("fitting"), held_out = committed_corpus("held_out");
  EXPECT_GT(fitting.frame_count() * kCorpusFrameS, 120.0);
  EXPECT_GT(held_out.frame_count() * kCorpusFrameS, 60.0);
  for (const CorpusSequence& a : fitting.sequences)
    for (const CorpusSequence& b : held_out.sequences) EXPECT_NE(a.frames, b.frames) << a.name << " " << b.name;
}

}  // namespace
}  // namespace fw::physics
