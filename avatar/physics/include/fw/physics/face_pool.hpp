#pragma once
// Many faces stepped in parallel (the behavioral-animation paper, sec. 3.2,
// spreads one face over the processors; a server with hundreds of avatars
// does better giving each thread whole faces: no sharing, no locks inside a
// step). A fixed pool of threads sized to the machine; the caller's thread
// works too and the call returns when every face is done.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "fw/physics/face_simulation.hpp"

namespace fw::physics {

/// Steps `faces` on the caller's thread as FacePool::step_all does: the
/// projective faces of one model in batches of up to max_batch_faces() that
/// share each solve, every other face on its own; a face at rest only
/// advances its clock. A face ends the same whichever faces it is batched
/// with (the solve runs lane by lane across them), so a server may gather
/// the faces of many rooms into one call.
void step_together(std::span<FaceSimulation* const> faces, double dt_seconds);
/// The most faces one projective solve takes at once.
std::size_t max_batch_faces();
/// Faces with the same key can share a solve of step_together: the model
/// whose factorisation they solve with (every avatar's fitted face shares
/// the generic face's), not the face's own model.
const void* solve_key(const FaceSimulation& face);

class FacePool {
 public:
  /// @param[in] threads  threads in all, the caller's included; 0 = one per hardware thread
  explicit FacePool(unsigned threads = 0);
  ~FacePool();
  FacePool(const FacePool&) = delete;
  FacePool& operator=(const FacePool&) = delete;

  unsigned thread_count() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Steps every face that is not at rest by `dt_seconds`: projective faces
  /// of one model in batches of up to 16 that share each solve (a batch is
  /// one thread's job), every other face on its own.
  void step_all(std::span<FaceSimulation> faces, double dt_seconds);
  void step_all(std::span<FaceSimulation* const> faces, double dt_seconds);

  /// Runs job(i) for every i in [0, count), spread over the threads; returns
  /// when all are done. Jobs must not call back into the pool.
  void for_each(std::size_t count, const std::function<void(std::size_t)>& job);

 private:
  /// for_each, handing out `chunk` jobs per grab.
  void run(std::size_t count, std::size_t chunk, const std::function<void(std::size_t)>& job);
  void work();
  void drain();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t count_ = 0, chunk_ = 1;
  std::atomic<std::size_t> next_{0};
  std::size_t busy_ = 0;
  std::size_t generation_ = 0;
  bool stopping_ = false;
};

}  // namespace fw::physics
