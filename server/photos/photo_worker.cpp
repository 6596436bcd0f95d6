#include "photo_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "avatar_store.hpp"
#include "fw/photo/photo_limits.hpp"
#include "fw/photo/prepare_avatar.hpp"

namespace fw::server {

static_assert(kMaxStoredPhotoBytes == photo::kMaxPhotoBytes, "a stored photo is one the preparer takes");

namespace {

/// The owner of stored avatars prepared again: no address, so they take
/// their turns beside the uploaders.
constexpr const char* kStoredAvatars = "(stored avatars)";

/// How long a thread after the first lets a job wait for the threads
/// before it, which may be just finishing theirs.
constexpr auto kGrace = std::chrono::milliseconds(250);

/// Which worker and thread the calling thread is, for preparer().
thread_local const PhotoWorker* t_worker = nullptr;
thread_local std::size_t t_index = 0;

}  // namespace

PhotoWorker::PhotoWorker(std::string landmark_model, std::size_t threads, std::size_t queue_limit)
    : landmark_model_(std::move(landmark_model)), preparers_(std::max<std::size_t>(threads, 1)),
      queue_(queue_limit, std::max<std::size_t>(preparers_.size() - 1, 1)), busy_(preparers_.size(), false) {
  for (std::size_t i = 0; i < preparers_.size(); ++i) threads_.emplace_back([this, i] { run(i); });
}

PhotoWorker::~PhotoWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (auto& thread : threads_) thread.join();
}

// notify_all: the thread whose turn it is may not be the one notify_one wakes.
bool PhotoWorker::try_post(const std::string& owner, std::function<void()> job) {
  {
    std::lock_guard lock(mutex_);
    if (!queue_.push_bounded(owner, std::move(job))) return false;
  }
  changed_.notify_all();
  return true;
}

void PhotoWorker::post(std::function<void()> job) {
  {
    std::lock_guard lock(mutex_);
    queue_.push(kStoredAvatars, std::move(job));
  }
  changed_.notify_all();
}

bool PhotoWorker::full() const {
  std::lock_guard lock(mutex_);
  return queue_.full();
}

bool PhotoWorker::full_for(const std::string& owner) const {
  std::lock_guard lock(mutex_);
  return queue_.full_for(owner);
}

int PhotoWorker::expected_wait_seconds() const {
  std::lock_guard lock(mutex_);
  const double ahead = static_cast<double>(queue_.waiting() + queue_.running());
  const double seconds = std::ceil(seconds_per_job_ * (ahead + 1) / static_cast<double>(threads_.size()));
  return static_cast<int>(std::clamp(seconds, 1.0, 600.0));
}

bool PhotoWorker::earlier_threads_busy(std::size_t index) const {
  return std::all_of(busy_.begin(), busy_.begin() + static_cast<std::ptrdiff_t>(index), [](bool busy) { return busy; });
}

void PhotoWorker::run(std::size_t index) {
  t_worker = this;
  t_index = index;
  std::unique_lock lock(mutex_);
  for (;;) {
    // A thread takes a job only while the threads before it are all busy,
    // so a second preparer (and its model) is made only when two photos
    // are prepared at once.
    changed_.wait(lock, [&] {
      return (earlier_threads_busy(index) && queue_.ready()) || (stopping_ && queue_.waiting() == 0);
    });
    if (!queue_.ready()) return;  // stopping, and nothing is left
    if (index > 0) {
      // Another job, and the first thread still busy: it may be just
      // finishing (its answer already out, the next upload already in). A
      // moment's grace lets it take the job itself, so that sequential
      // uploads stay on one thread and its model.
      const auto until = std::chrono::steady_clock::now() + kGrace;
      changed_.wait_until(lock, until, [&] { return stopping_ || std::chrono::steady_clock::now() >= until; });
      if (!earlier_threads_busy(index)) continue;
    }
    auto taken = queue_.take();
    if (!taken) continue;
    busy_[index] = true;
    // The next thread's turn may have come with this one busy.
    if (queue_.ready()) changed_.notify_all();
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    taken->job();
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    taken->job = nullptr;  // what it held (a request's body) goes before the lock is taken
    lock.lock();
    seconds_per_job_ = 0.8 * seconds_per_job_ + 0.2 * took;
    busy_[index] = false;
    queue_.finished(taken->owner);
    changed_.notify_all();  // the owner's next photo may go now
  }
}

photo::AvatarPreparer* PhotoWorker::preparer(photo::PrepError& error) {
  if (t_worker != this) {
    error.message = "photos are prepared on the photo worker's threads only";
    return nullptr;
  }
  auto& preparer = preparers_[t_index];
  if (!preparer) {
    const auto model = landmark_model_.empty() ? std::nullopt
                                               : std::optional<std::filesystem::path>(landmark_model_);
    preparer = photo::AvatarPreparer::create(model, error);
  }
  return preparer.get();
}

}  // namespace fw::server
