#include "fw/physics/face_pool.hpp"

#include <algorithm>

#include "projective_dynamics.hpp"
#include "projective_system.hpp"

namespace fw::physics {
namespace {

// Faces handed out per grab: enough to make the atomic negligible, few
// enough that the threads finish together.
constexpr std::size_t kChunk = 4;

}  // namespace

FacePool::FacePool(unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

FacePool::~FacePool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void FacePool::drain() {
  for (;;) {
    const std::size_t begin = next_.fetch_add(chunk_, std::memory_order_relaxed);
    if (begin >= count_) return;
    const std::size_t end = std::min(count_, begin + chunk_);
    for (std::size_t i = begin; i < end; ++i) (*job_)(i);
  }
}

void FacePool::work() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    drain();
    {
      std::lock_guard lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }
}

void FacePool::for_each(std::size_t count, const std::function<void(std::size_t)>& job) { run(count, kChunk, job); }

void FacePool::run(std::size_t count, std::size_t chunk, const std::function<void(std::size_t)>& job) {
  if (count == 0) return;
  if (workers_.empty() || count <= chunk) {
    for (std::size_t i = 0; i < count; ++i) job(i);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    count_ = count;
    chunk_ = chunk;
    next_.store(0, std::memory_order_relaxed);
    busy_ = workers_.size();
    ++generation_;
  }
  wake_.notify_all();
  drain();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
  job_ = nullptr;
}

void FacePool::step_all(std::span<FaceSimulation> faces, double dt_seconds) {
  std::vector<FaceSimulation*> pointers(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) pointers[i] = &faces[i];
  step_all(std::span<FaceSimulation* const>(pointers), dt_seconds);
}

namespace {

// Projective faces that share a factorisation (one model, or fitted faces
// of the generic one's topology) go in batches that share each solve
// (projective_dynamics.hpp); every other face is a job of its own. The
// projective faces are gathered in `projective`, which the jobs view.
std::vector<std::span<FaceSimulation* const>> step_jobs(std::span<FaceSimulation* const> faces,
                                                        std::vector<FaceSimulation*>& projective) {
  std::vector<std::span<FaceSimulation* const>> jobs;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i]->options().solver == Solver::projective && !faces[i]->at_rest()) projective.push_back(faces[i]);
    else jobs.push_back(faces.subspan(i, 1));
  }
  std::stable_sort(projective.begin(), projective.end(),
                   [](const FaceSimulation* a, const FaceSimulation* b) { return factor_owner(*a) < factor_owner(*b); });
  for (std::size_t begin = 0; begin < projective.size();) {
    std::size_t end = begin + 1;
    while (end < projective.size() && end - begin < detail::kMaxBatchFaces &&
           factor_owner(*projective[end]) == factor_owner(*projective[begin]))
      ++end;
    jobs.push_back(std::span<FaceSimulation* const>(projective).subspan(begin, end - begin));
    begin = end;
  }
  return jobs;
}

void step_job(std::span<FaceSimulation* const> job, double dt_seconds) {
  if (job.size() == 1 && job[0]->options().solver != Solver::projective) job[0]->step(dt_seconds);
  else ProjectiveStepper::step(job, dt_seconds);
}

}  // namespace

void FacePool::step_all(std::span<FaceSimulation* const> faces, double dt_seconds) {
  // A face at rest only advances its clock.
  std::vector<FaceSimulation*> projective;
  const auto jobs = step_jobs(faces, projective);
  // A batch is a big job: one per grab, so that both threads get some.
  run(jobs.size(), 1, [&](std::size_t j) { step_job(jobs[j], dt_seconds); });
}

void step_together(std::span<FaceSimulation* const> faces, double dt_seconds) {
  std::vector<FaceSimulation*> projective;
  for (const auto job : step_jobs(faces, projective)) step_job(job, dt_seconds);
}

std::size_t max_batch_faces() { return detail::kMaxBatchFaces; }

const void* solve_key(const FaceSimulation& face) { return factor_owner(face); }

}  // namespace fw::physics
