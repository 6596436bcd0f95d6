#pragma once
// A gate a test closes on the face stepper's batches: the worker that steps
// waits there (at most 30 s), and the rooms that hand their faces over
// meanwhile wait for it with their ticks under way, as on a busy pool.
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace fw::server {

class StepGate {
 public:
  void close() {
    const std::lock_guard lock(mutex_);
    open_ = false;
  }
  void open() {
    {
      const std::lock_guard lock(mutex_);
      open_ = true;
    }
    opened_.notify_all();
  }
  void pass() {
    std::unique_lock lock(mutex_);
    opened_.wait_for(lock, std::chrono::seconds(30), [this] { return open_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable opened_;
  bool open_ = true;
};

}  // namespace fw::server
