#include "face_stepper.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::server {

FaceStepper::FaceStepper(std::function<void(double seconds)> stepped) : stepped_(std::move(stepped)) {}

void FaceStepper::step(std::vector<physics::FaceSimulation*> faces, double dt_s, std::function<void()> done) {
  if (faces.empty()) return done();
  auto hand_over = std::make_shared<HandOver>();
  hand_over->left = faces.size();
  hand_over->faces = std::move(faces);
  hand_over->dt_s = dt_s;
  hand_over->done = std::move(done);
  std::unique_lock lock(mutex_);
  for (physics::FaceSimulation* face : hand_over->faces) waiting_.push_back({face, hand_over});
  // This worker steps while nobody else does, or while a full batch waits
  // (then the workers share the tissue's work).
  while (!waiting_.empty() && (stepping_ == 0 || waiting_.size() >= physics::max_batch_faces())) {
    ++stepping_;
    const std::vector<Entry> batch = take_batch();
    lock.unlock();
    const auto finished = run_batch(batch);
    for (const auto& done_with : finished) done_with->done();
    lock.lock();
    --stepping_;
  }
}

std::vector<FaceStepper::Entry> FaceStepper::take_batch() {
  // The oldest waiting face leads; the faces that share its solve and its
  // step length behind it join, up to what one solve takes. Every avatar's
  // own face shares the generic face's factorisation (physics::solve_key):
  // taking only the faces of one avatar's model, as before, made solves of
  // 2 to 8 faces at 100 rooms of 10, since few wear the same face.
  std::vector<Entry> batch;
  const void* key = physics::solve_key(*waiting_.front().face);
  const double dt_s = waiting_.front().from->dt_s;
  for (auto it = waiting_.begin(); it != waiting_.end() && batch.size() < physics::max_batch_faces();) {
    if (physics::solve_key(*it->face) == key && it->from->dt_s == dt_s) {
      batch.push_back(std::move(*it));
      it = waiting_.erase(it);
    } else {
      ++it;
    }
  }
  faces_.fetch_add(batch.size(), std::memory_order_relaxed);
  batches_.fetch_add(1, std::memory_order_relaxed);
  return batch;
}

void FaceStepper::step_here(const std::vector<physics::FaceSimulation*>& faces, double dt_s) {
  physics::step_together(faces, dt_s);
}

std::vector<std::shared_ptr<FaceStepper::HandOver>> FaceStepper::run_batch(const std::vector<Entry>& batch) {
  std::vector<physics::FaceSimulation*> faces;
  faces.reserve(batch.size());
  for (const Entry& entry : batch) faces.push_back(entry.face);
  const auto start = std::chrono::steady_clock::now();
  physics::step_together(faces, batch.front().from->dt_s);
  if (stepped_) stepped_(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  // A hand-over is done with its last face, whichever batch stepped it.
  std::vector<std::shared_ptr<HandOver>> finished;
  for (const Entry& entry : batch)
    if (entry.from->left.fetch_sub(1, std::memory_order_acq_rel) == 1) finished.push_back(entry.from);
  return finished;
}

}  // namespace fw::server
