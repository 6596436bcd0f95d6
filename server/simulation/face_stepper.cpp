#include "face_stepper.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::server {

FaceStepper::FaceStepper(Post post, std::function<void(double seconds)> stepped)
    : post_(std::move(post)), stepped_(std::move(stepped)) {}

void FaceStepper::step(std::vector<physics::FaceSimulation*> faces, double dt_s, std::function<void()> done) {
  if (faces.empty()) return done();
  auto hand_over = std::make_shared<HandOver>();
  hand_over->left = faces.size();
  hand_over->faces = std::move(faces);
  hand_over->dt_s = dt_s;
  hand_over->done = std::move(done);
  bool post_flush = false;
  {
    const std::lock_guard lock(mutex_);
    waiting_.push_back(std::move(hand_over));
    post_flush = !std::exchange(flush_posted_, true);
  }
  // Posted behind what the pool already holds: the ticks of the rooms due
  // about now run first and hand their faces over too.
  if (post_flush) post_([this] { flush(); });
}

void FaceStepper::flush() {
  std::vector<std::shared_ptr<HandOver>> taken;
  {
    const std::lock_guard lock(mutex_);
    taken.swap(waiting_);
    flush_posted_ = false;
  }
  std::vector<Entry> entries;
  for (const auto& hand_over : taken)
    for (physics::FaceSimulation* face : hand_over->faces) entries.push_back({face, hand_over});
  // Faces of one step length and one model side by side (hand-over order
  // kept within them), then cut into batches of what one solve takes.
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    if (a.from->dt_s != b.from->dt_s) return a.from->dt_s < b.from->dt_s;
    return &a.face->model() < &b.face->model();
  });
  std::vector<std::vector<Entry>> batches;
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin + 1;
    while (end < entries.size() && end - begin < physics::max_batch_faces() &&
           entries[end].from->dt_s == entries[begin].from->dt_s &&
           &entries[end].face->model() == &entries[begin].face->model())
      ++end;
    batches.emplace_back(entries.begin() + static_cast<std::ptrdiff_t>(begin),
                         entries.begin() + static_cast<std::ptrdiff_t>(end));
    begin = end;
  }
  faces_.fetch_add(entries.size(), std::memory_order_relaxed);
  batches_.fetch_add(batches.size(), std::memory_order_relaxed);
  // Every batch but the last to the pool, so that the other workers take
  // some; the last on this thread, which is one of them.
  for (std::size_t b = 0; b + 1 < batches.size(); ++b)
    post_([this, batch = std::move(batches[b])] { run_batch(batch); });
  if (!batches.empty()) run_batch(batches.back());
}

void FaceStepper::step_here(const std::vector<physics::FaceSimulation*>& faces, double dt_s) {
  physics::step_together(faces, dt_s);
}

void FaceStepper::run_batch(const std::vector<Entry>& batch) {
  std::vector<physics::FaceSimulation*> faces;
  faces.reserve(batch.size());
  for (const Entry& entry : batch) faces.push_back(entry.face);
  const auto start = std::chrono::steady_clock::now();
  physics::step_together(faces, batch.front().from->dt_s);
  if (stepped_) stepped_(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  // A hand-over is done with its last face, whichever batch stepped it.
  for (const Entry& entry : batch)
    if (entry.from->left.fetch_sub(1, std::memory_order_acq_rel) == 1) entry.from->done();
}

}  // namespace fw::server
