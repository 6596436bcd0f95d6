#pragma once
// The one thread that prepares photos (dlib and OpenCV, about a second of
// CPU each, so neither I/O nor rooms wait on it): uploads and stored avatars
// prepared again take their turns on it. dlib's detector is not thread-safe,
// so the preparer lives on this thread alone; its landmark model loads on
// first use, not at start.
#include <functional>
#include <memory>
#include <string>

#include <boost/asio/thread_pool.hpp>

namespace fw::photo {
class AvatarPreparer;
struct PrepError;
}  // namespace fw::photo

namespace fw::server {

class PhotoWorker {
 public:
  /// `landmark_model`: dlib's model file; empty: the default place.
  explicit PhotoWorker(std::string landmark_model);
  /// Waits for the jobs already posted.
  ~PhotoWorker();
  PhotoWorker(const PhotoWorker&) = delete;
  PhotoWorker& operator=(const PhotoWorker&) = delete;

  /// Runs `job` on the worker's thread, after the jobs posted before it.
  void post(std::function<void()> job);

  /// On the worker's thread only: the preparer, its model loaded on the
  /// first call; null and `error` when this server cannot prepare photos.
  photo::AvatarPreparer* preparer(photo::PrepError& error);

 private:
  std::string landmark_model_;
  std::unique_ptr<photo::AvatarPreparer> preparer_;
  boost::asio::thread_pool pool_{1};  ///< last: joined before the preparer goes
};

}  // namespace fw::server
