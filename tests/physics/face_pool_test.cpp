#include "fw/physics/face_pool.hpp"

#include <atomic>

#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"

namespace fw::physics {
namespace {

std::vector<FaceSimulation> faces(std::size_t n, Solver solver) {
  static const auto tissue = build_tissue_model(model::generic_face(), model::generic_face().action_units);
  std::vector<FaceSimulation> out;
  for (std::size_t i = 0; i < n; ++i) {
    SimulationOptions options;
    options.solver = solver;
    options.seed = i;
    options.individual_variation = 0.05f;
    options.course_variation = 0.05f;
    out.emplace_back(tissue, options);
    std::array<float, codec::kAuChannelCount> targets{};
    targets[i % codec::kAuChannelCount] = 1.0f;
    if (i % 3 != 2) out.back().set_action_units(targets);  // every third face stays asleep
  }
  return out;
}

TEST(FacePool, SizesItselfToTheMachine) {
  FacePool pool;
  EXPECT_GE(pool.thread_count(), 1u);
  EXPECT_EQ(FacePool(3).thread_count(), 3u);
}

TEST(FacePool, RunsEveryJobOnce) {
  FacePool pool(4);
  std::vector<std::atomic<int>> runs(1001);
  for (int repeat = 0; repeat < 5; ++repeat) pool.for_each(runs.size(), [&](std::size_t i) { ++runs[i]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 5);
}

// Threads change nothing: each face is stepped by one thread at a time.
TEST(FacePool, StepsManyFacesExactlyAsOneThreadWould) {
  for (Solver solver : {Solver::mass_spring, Solver::pbd, Solver::projective}) {
    auto parallel = faces(23, solver), serial = faces(23, solver);
    FacePool pool(3);
    for (int f = 0; f < 10; ++f) {
      pool.step_all(std::span<FaceSimulation>(parallel), 1.0 / 30);
      for (FaceSimulation& face : serial) face.step(1.0 / 30);
    }
    for (std::size_t i = 0; i < parallel.size(); ++i) {
      EXPECT_EQ(parallel[i].surface(), serial[i].surface()) << "face " << i;
      EXPECT_EQ(parallel[i].time_s(), serial[i].time_s());
    }
  }
}

TEST(FacePool, StepsFacesHeldByPointer) {
  auto owned = faces(6, Solver::mass_spring);
  std::vector<FaceSimulation*> pointers;
  for (auto& f : owned) pointers.push_back(&f);
  FacePool pool(2);
  pool.step_all(std::span<FaceSimulation* const>(pointers), 0.1);
  for (const auto& f : owned) EXPECT_DOUBLE_EQ(f.time_s(), 0.1);
}

}  // namespace
}  // namespace fw::physics
