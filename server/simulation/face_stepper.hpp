#pragma once
// The physics faces of many rooms stepped together on the worker pool.
//
// A projective solve costs about as much for 16 faces as for 2 (avatar/physics
// face_pool.hpp: the faces' right-hand sides run lane by lane through one
// factored matrix, which every avatar's fitted face shares with the generic
// face: physics::solve_key), but a room of 10 has only the few
// faces that are awake and allowed physics in a tick. So a room's tick comes
// in two halves (RoomSimulation::begin_tick, finish_tick) and in between the
// room hands its faces here. The worker that hands faces over steps what
// waits, in batches of up to physics::max_batch_faces() sharing a solve, while
// nobody else does or while a full batch waits; the hand-overs of rooms
// whose ticks come meanwhile (on the other workers) wait for it and join
// the next batch, so the busier the pool, the fuller the batches. Nothing
// waits for a timer or a queue of its own: with the pool idle, a room's
// faces are stepped at once, by its own worker.
//
// A hand-over's `done` runs on the worker that stepped its last face: for
// the room that handed over last it is the room's own worker, still inside
// its handler (Room::end_tick then runs inline, on its strand).
//
// Threading: a room's faces belong to this stepper from the hand-over until
// `done`; the room touches neither them nor its simulation meanwhile (Room
// holds the requests that arrive until its tick is finished). A face ends
// the same whatever it is batched with, so each room stays deterministic.
// Thread-safe.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace fw::physics {
class FaceSimulation;
}

namespace fw::server {

class FaceStepper {
 public:
  /// `stepped` hears the seconds each batch took (PhysicsGovernor::observe_physics_work).
  explicit FaceStepper(std::function<void(double seconds)> stepped = {});

  /// Steps `faces` by `dt_s` with those handed over about the same time;
  /// `done` runs once all of them are stepped: on this thread before the
  /// call returns, or on the worker that steps them later.
  void step(std::vector<physics::FaceSimulation*> faces, double dt_s, std::function<void()> done);

  /// Steps `faces` on this thread, together, as a hand-over would be.
  static void step_here(const std::vector<physics::FaceSimulation*>& faces, double dt_s);

  /// Faces handed over and not yet taken into a batch.
  std::size_t waiting() const {
    const std::lock_guard lock(mutex_);
    return waiting_.size();
  }

  /// Faces stepped and the batches (solves) they took, since the start.
  std::uint64_t faces_stepped() const { return faces_.load(std::memory_order_relaxed); }
  std::uint64_t batches() const { return batches_.load(std::memory_order_relaxed); }

 private:
  struct HandOver {
    std::vector<physics::FaceSimulation*> faces;
    double dt_s = 0;
    std::function<void()> done;
    std::atomic<std::size_t> left{0};  ///< faces not yet stepped
  };
  struct Entry {
    physics::FaceSimulation* face;
    std::shared_ptr<HandOver> from;
  };
  /// Takes the next batch from waiting_ (under mutex_): the faces that share
  /// the first waiting face's solve and step, up to a solve's worth.
  std::vector<Entry> take_batch();
  /// Steps a batch; the hand-overs it completes.
  std::vector<std::shared_ptr<HandOver>> run_batch(const std::vector<Entry>& batch);

  std::function<void(double)> stepped_;
  mutable std::mutex mutex_;
  std::deque<Entry> waiting_;
  int stepping_ = 0;  ///< workers stepping now
  std::atomic<std::uint64_t> faces_{0}, batches_{0};
};

}  // namespace fw::server
