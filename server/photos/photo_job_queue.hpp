#pragma once
// The photos waiting to be prepared, taken in turn rather than in order of
// arrival: first by network block (address_group(): the /24 or /48 of the
// uploader's address), then, within a block, by owner (the uploader's
// address_key()). One address that sends a burst of slow photos (PNG bombs
// of 40 megapixels) then delays another person's photo by at most the
// photo it has in preparation, not by all of its queue; and many addresses
// rented in one block get one block's turn, not one turn each. An owner has
// at most one photo in preparation at a time, and a block at most
// `running_per_block` (PhotoWorker keeps one thread for other blocks), so
// another block's photo never waits behind a block that holds every thread.
// Waiting uploads are bounded (the limit), and one block may fill at most
// half of the places (at least one), so that a block cannot fill the queue
// for everyone; jobs posted unbounded (stored avatars prepared again, which
// must not be refused) do not count toward either. Not thread-safe:
// PhotoWorker holds its lock.
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>
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

  explicit PhotoJobQueue(std::size_t limit,
                         std::size_t running_per_block = std::numeric_limits<std::size_t>::max());

  /// Queues an upload's `job` for `owner`; false (and nothing queued) when
  /// the queue, or the places of `owner`'s block, are full.
  bool push_bounded(const std::string& owner, Job job);
  /// Queues `job` for `owner` whatever the queue holds.
  void push(const std::string& owner, Job job);

  /// The next job to run: the first block in turn that runs fewer than its
  /// share, and in it the first owner in turn with a job waiting and none
  /// running. nullopt when there is none. The caller runs it, then calls
  /// finished().
  std::optional<Taken> take();
  /// Whether take() would give a job.
  bool ready() const;
  void finished(const std::string& owner);

  /// Uploads waiting (the bounded ones), and all jobs waiting.
  std::size_t waiting_uploads() const { return waiting_uploads_; }
  std::size_t waiting() const { return waiting_; }
  std::size_t running() const { return running_total_; }
  bool full() const { return waiting_uploads_ >= limit_; }
  /// Whether an upload of `owner` would be refused: the queue is full, or
  /// its block holds its share of the places.
  bool full_for(const std::string& owner) const;
  /// The places one block may hold.
  std::size_t block_places() const { return block_places_; }

 private:
  struct Entry {
    Job job;
    bool bounded = false;
  };
  struct Block {
    std::deque<std::string> turns;  ///< its owners with jobs waiting, each once, in turn
    std::size_t running = 0;
    std::size_t waiting_uploads = 0;
  };
  void add(const std::string& owner, Entry entry);
  /// The block whose turn it is and, in it, the owner whose turn it is.
  struct Next {
    std::deque<std::string>::const_iterator block;
    std::deque<std::string>::const_iterator owner;
  };
  std::optional<Next> next() const;

  std::size_t limit_;
  std::size_t running_per_block_;
  std::size_t block_places_;
  std::map<std::string, std::deque<Entry>> jobs_;  ///< by owner, in order of arrival
  std::map<std::string, Block> blocks_;            ///< blocks with jobs waiting or running
  std::deque<std::string> turns_;                  ///< blocks with jobs waiting, each once, in turn
  std::map<std::string, std::size_t> running_;    ///< owners with a job running
  std::size_t waiting_uploads_ = 0;
  std::size_t waiting_ = 0;
  std::size_t running_total_ = 0;
};

}  // namespace fw::server
