#pragma once
// The physics faces of many rooms stepped together on the worker pool.
//
// A projective solve costs about as much for 16 faces of one tissue model as
// for 2 (avatar/physics face_pool.hpp: the faces' right-hand sides run lane
// by lane through one factored matrix), but a room of 10 has only the few
// faces that are awake and allowed physics in a tick. So a room's tick comes
// in two halves (RoomSimulation::begin_tick, finish_tick) and in between the
// room hands its faces here. Hand-overs wait until the pool reaches the
// flush that the first of them posted: by then the rooms whose ticks fell
// due together have handed theirs too (the busier the pool, the more), and
// the faces go out in batches of up to physics::max_batch_faces() of one
// model, one pool job each. A hand-over's `done` runs on the pool thread
// that stepped its last face.
//
// Threading: a room's faces belong to this stepper from the hand-over until
// `done`; the room touches neither them nor its simulation meanwhile (Room
// holds the requests that arrive until its tick is finished). A face ends
// the same whatever it is batched with, so each room stays deterministic.
// Thread-safe.
#include <atomic>
#include <cstddef>
#include <cstdint>
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
  /// Runs a job later on the pool (never inline).
  using Post = std::function<void(std::function<void()>)>;

  /// `stepped` hears the seconds each batch took (PhysicsGovernor::observe_physics_work).
  explicit FaceStepper(Post post, std::function<void(double seconds)> stepped = {});

  /// Steps `faces` by `dt_s` with those handed over about the same time;
  /// `done` runs once all of them are stepped (inline, at once, if there
  /// are none).
  void step(std::vector<physics::FaceSimulation*> faces, double dt_s, std::function<void()> done);

  /// Steps `faces` on this thread, together, as a hand-over would be.
  static void step_here(const std::vector<physics::FaceSimulation*>& faces, double dt_s);

  /// Faces stepped and the pool jobs (batches) they took, since the start.
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
  /// Steps every hand-over waiting, in batches, one pool job each (the last
  /// on this thread).
  void flush();
  void run_batch(const std::vector<Entry>& batch);

  Post post_;
  std::function<void(double)> stepped_;
  std::mutex mutex_;
  std::vector<std::shared_ptr<HandOver>> waiting_;
  bool flush_posted_ = false;
  std::atomic<std::uint64_t> faces_{0}, batches_{0};
};

}  // namespace fw::server
