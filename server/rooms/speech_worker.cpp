#include "speech_worker.hpp"

#include <boost/asio/post.hpp>

namespace fw::server {

SpeechWorker::SpeechWorker(std::size_t threads, std::size_t max_queued) : max_queued_(max_queued) {
  threads_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) threads_.emplace_back([this] { run(); });
}

SpeechWorker::~SpeechWorker() { stop(); }

bool SpeechWorker::submit(std::function<void()> job) {
  {
    const std::lock_guard lock(mutex_);
    if (stopping_ || jobs_.size() >= max_queued_) return false;
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
  return true;
}

std::size_t SpeechWorker::queued() const {
  const std::lock_guard lock(mutex_);
  return jobs_.size();
}

void SpeechWorker::stop() {
  {
    const std::lock_guard lock(mutex_);
    if (stopping_ && threads_.empty()) return;
    stopping_ = true;
    jobs_.clear();
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
  threads_.clear();
}

void SpeechWorker::run() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      if (stopping_) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();
  }
}

bool RoomTrackMaker::make(LineJob job, std::function<void(LineJob, LineToSay)> done) {
  const bool queued = worker_.submit([strand = strand_, room = room_, job = std::move(job), done = std::move(done)]() mutable {
    LineToSay line = make_line(job.text, job.language);
    boost::asio::post(strand, [room = std::move(room), job = std::move(job), line = std::move(line),
                               done = std::move(done)]() mutable {
      // Held for the call: the room, and so the simulation `done` starts
      // the line in, cannot go while it runs.
      if (const auto alive = room.lock()) done(std::move(job), std::move(line));
    });
  });
  if (!queued) refused_.fetch_add(1, std::memory_order_relaxed);
  return queued;
}

}  // namespace fw::server
