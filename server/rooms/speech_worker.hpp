#pragma once
// The threads that make chat lines' lip-sync tracks for every room of the
// server, so that no room's tick waits for espeak-ng: a 500-byte line takes
// tens of milliseconds (a tick is 33 ms), and espeak-ng says one line at a
// time in the whole process (avatar/speech's engine mutex). A room hands a
// line here (RoomTrackMaker) and gets its track back on its own strand;
// its line starts then.
//
// Bounded: at most `max_queued` lines wait for a thread. A line that finds
// the queue full is not said (it is still shown as chat), and its writer is
// told so (RoomSimulation: "your line is shown but not said: the server is
// busy saying other lines"). At 5 lines a second per room (the room chat
// rate) and a few ms per line, the queue fills only when many rooms chat
// at their limits at once; then losing voices beats losing ticks.
// Thread-safe: any thread submits; stop() and the destructor from one.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>

#include "track_maker.hpp"

namespace fw::server {

class SpeechWorker {
 public:
  /// @param[in] threads     1 .. 8 threads that make tracks
  /// @param[in] max_queued  jobs that may wait for a thread, 1 ..
  SpeechWorker(std::size_t threads, std::size_t max_queued);
  ~SpeechWorker();
  SpeechWorker(const SpeechWorker&) = delete;
  SpeechWorker& operator=(const SpeechWorker&) = delete;

  /// Queues `job` for a thread; false (and `job` dropped) when max_queued
  /// jobs wait already, or after stop().
  bool submit(std::function<void()> job);
  /// Jobs waiting for a thread now.
  std::size_t queued() const;
  /// Runs no more jobs: those still queued are dropped, the threads end
  /// after the jobs they are running.
  void stop();

 private:
  void run();

  const std::size_t max_queued_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

/// A room's TrackMaker on the server's SpeechWorker: the track is made on a
/// worker thread, and `done` runs on the room's strand, if the room that
/// bind() named still exists by then (a room closed meanwhile drops it).
class RoomTrackMaker final : public TrackMaker {
 public:
  using Strand = boost::asio::strand<boost::asio::thread_pool::executor_type>;
  /// `refused` counts the lines the worker's full queue turned away
  /// (Metrics::unsaid_lines), so that an operator sees voices lost to load.
  RoomTrackMaker(SpeechWorker& worker, Strand strand, std::atomic<std::uint64_t>& refused)
      : worker_(worker), strand_(std::move(strand)), refused_(refused) {}
  /// The room whose life the tracks handed back depend on (before any line).
  void bind(std::weak_ptr<const void> room) { room_ = std::move(room); }
  bool make(LineJob job, std::function<void(LineJob, LineToSay)> done) override;

 private:
  SpeechWorker& worker_;
  Strand strand_;
  std::atomic<std::uint64_t>& refused_;
  std::weak_ptr<const void> room_;
};

}  // namespace fw::server
