#pragma once
// The photos waiting to be prepared, taken in turn by owner (the uploader's
// address_key()) rather than in order of arrival: one address that sends a
// burst of slow photos (PNG bombs of 40 megapixels) then delays another
// person's photo by at most the photo it has in preparation, not by all of
// its queue. An owner also has at most one photo in preparation at a time,
// so with two preparing threads another person's photo never waits behind
// one address at all. Waiting uploads are bounded (the limit); jobs posted
// unbounded (stored avatars prepared again, which must not be refused) do
// not count toward it. Not thread-safe: PhotoWorker holds its lock.
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace fw::server {

class PhotoJobQueue {
 public:
  using Job = std::function<void()>;
  struct Taken {
    std::string owner;
    Job job;
  };

  explicit PhotoJobQueue(std::size_t limit) : limit_(limit) {}

  /// Queues an upload's `job` for `owner`; false (and nothing queued) when
  /// `limit` uploads already wait.
  bool push_bounded(const std::string& owner, Job job);
  /// Queues `job` for `owner` whatever the queue holds.
  void push(const std::string& owner, Job job);

  /// The next job to run: the first owner in turn with a job waiting and
  /// none running. nullopt when there is none (all waiting jobs belong to
  /// owners with one running). The caller runs it, then calls finished().
  std::optional<Taken> take();
  /// Whether take() would give a job.
  bool ready() const;
  void finished(const std::string& owner);

  /// Uploads waiting (the bounded ones), and all jobs waiting.
  std::size_t waiting_uploads() const { return waiting_uploads_; }
  std::size_t waiting() const { return waiting_; }
  std::size_t running() const { return running_total_; }
  bool full() const { return waiting_uploads_ >= limit_; }

 private:
  struct Entry {
    Job job;
    bool bounded = false;
  };
  void add(const std::string& owner, Entry entry);

  std::size_t limit_;
  std::map<std::string, std::deque<Entry>> jobs_;  ///< by owner, in order of arrival
  std::deque<std::string> turns_;                  ///< owners with jobs waiting, each once, in turn
  std::map<std::string, std::size_t> running_;    ///< owners with a job running
  std::size_t waiting_uploads_ = 0;
  std::size_t waiting_ = 0;
  std::size_t running_total_ = 0;
};

}  // namespace fw::server
