#pragma once
// The threads that prepare photos (dlib and OpenCV, about a second of CPU
// each, so neither I/O nor rooms wait on them): uploads and stored avatars
// prepared again take their turns on them, by network block and by owner
// (photo_job_queue.hpp: one address's burst of photos does not hold up
// another's, nor do many addresses of one block). With more than one
// thread, a block prepares at most one photo fewer than there are threads
// at once, so that one is always left for another block's photo. dlib's
// detector is not thread-safe, so each thread has its own preparer; its
// landmark model (about 100 MB) loads on the thread's first photo, not at
// start. At most `queue_limit` uploads wait; more are refused, so that a
// flood of photos neither grows memory nor delays everyone by minutes.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "photo_job_queue.hpp"

namespace fw::photo {
class AvatarPreparer;
struct PrepError;
}  // namespace fw::photo

namespace fw::server {

class PhotoWorker {
 public:
  /// `landmark_model`: dlib's model file; empty: the default place.
  /// `threads`: photos prepared at once (at least 1); a thread after the
  /// first only starts (and loads its model) while the ones before it are busy.
  explicit PhotoWorker(std::string landmark_model, std::size_t threads = 1,
                       std::size_t queue_limit = std::numeric_limits<std::size_t>::max());
  /// Runs the jobs already queued, then stops.
  ~PhotoWorker();
  PhotoWorker(const PhotoWorker&) = delete;
  PhotoWorker& operator=(const PhotoWorker&) = delete;

  /// Queues an upload's `job` for `owner` (its address_key()); false when
  /// the queue is full (nothing queued: refuse the upload).
  bool try_post(const std::string& owner, std::function<void()> job);
  /// Queues `job` whatever the queue holds: stored avatars prepared again,
  /// which a person is already waiting for and which must not be refused.
  void post(std::function<void()> job);

  /// Whether an upload would be refused now (to refuse it from its header,
  /// before its body is read; try_post decides).
  bool full() const;
  /// The same for an upload of `owner`: the queue is full, or its block
  /// holds its share of the places (PhotoJobQueue::full_for).
  bool full_for(const std::string& owner) const;
  /// Seconds until a photo queued now would likely be done, from the
  /// photos ahead and how long photos took lately (at least 1).
  int expected_wait_seconds() const;
  std::size_t threads() const { return threads_.size(); }

  /// On a worker thread only: that thread's preparer, its model loaded on
  /// the first call; null and `error` when this server cannot prepare photos.
  photo::AvatarPreparer* preparer(photo::PrepError& error);

 private:
  void run(std::size_t index);
  /// Whether the threads before thread `index` are all preparing a photo.
  bool earlier_threads_busy(std::size_t index) const;

  std::string landmark_model_;
  std::vector<std::unique_ptr<photo::AvatarPreparer>> preparers_;  ///< one per thread, by index
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  PhotoJobQueue queue_;
  std::vector<bool> busy_;  ///< by thread index: preparing a photo
  bool stopping_ = false;
  double seconds_per_job_ = 2;  ///< a moving average; a photo's preparation until one is timed
  std::vector<std::thread> threads_;  ///< last: started once the rest is ready
};

}  // namespace fw::server
