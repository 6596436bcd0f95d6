// The photo worker's queue without photos: jobs taken in turn by network
// block and by owner (one address's burst, or many addresses of one /24, do
// not hold up another's photo), at most one job of an owner running at a
// time and a block held to its share of the threads, uploads bounded (and a
// block to half of the places) and refused when the queue is full, stored
// avatars prepared again never refused, and a second thread that takes a job
// only while the first is busy.
#include "photo_worker.hpp"

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "photo_job_queue.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;

/// Takes every job it can, in order, naming each by the owner it ran for;
/// each job is finished at once.
std::vector<std::string> drain(PhotoJobQueue& queue) {
  std::vector<std::string> order;
  while (auto taken = queue.take()) {
    taken->job();
    order.push_back(taken->owner);
    queue.finished(taken->owner);
  }
  return order;
}

TEST(PhotoJobQueue, OwnersTakeTurnsSoABurstDoesNotHoldUpAnotherPhoto) {
  PhotoJobQueue queue(100);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(queue.push_bounded("flood", [] {}));
  ASSERT_TRUE(queue.push_bounded("ann", [] {}));
  ASSERT_TRUE(queue.push_bounded("bob", [] {}));
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"flood", "ann", "bob", "flood", "flood", "flood", "flood"}));
  EXPECT_EQ(queue.waiting(), 0u);
}

TEST(PhotoJobQueue, AnOwnerHasOnePhotoInPreparationAtATime) {
  PhotoJobQueue queue(100);
  ASSERT_TRUE(queue.push_bounded("flood", [] {}));
  ASSERT_TRUE(queue.push_bounded("flood", [] {}));
  ASSERT_TRUE(queue.push_bounded("ann", [] {}));
  auto first = queue.take();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->owner, "flood");
  auto second = queue.take();
  ASSERT_TRUE(second) << "another owner's job is ready";
  EXPECT_EQ(second->owner, "ann");
  EXPECT_FALSE(queue.ready()) << "flood's second photo waits for its first";
  EXPECT_FALSE(queue.take());
  queue.finished("flood");
  EXPECT_TRUE(queue.ready());
  auto third = queue.take();
  ASSERT_TRUE(third);
  EXPECT_EQ(third->owner, "flood");
}

TEST(PhotoJobQueue, UploadsAreBoundedAndOtherJobsAreNot) {
  PhotoJobQueue queue(2);
  EXPECT_TRUE(queue.push_bounded("a", [] {}));
  EXPECT_TRUE(queue.push_bounded("b", [] {}));
  EXPECT_TRUE(queue.full());
  EXPECT_FALSE(queue.push_bounded("c", [] {})) << "a third upload waits past the limit";
  queue.push("stored", [] {});  // a stored avatar prepared again: never refused
  EXPECT_EQ(queue.waiting(), 3u);
  EXPECT_EQ(queue.waiting_uploads(), 2u);
  // Taking a job makes room: the limit is on photos waiting, not running.
  auto taken = queue.take();
  ASSERT_TRUE(taken);
  EXPECT_FALSE(queue.full());
  EXPECT_TRUE(queue.push_bounded("c", [] {}));
}

TEST(PhotoJobQueue, ManyAddressesOfOneBlockGetOneBlocksTurn) {
  PhotoJobQueue queue(100);
  // Five addresses rented in one /24, one photo each, then a person's
  // photo from another block: it waits for one of them, not for five.
  for (int i = 1; i <= 5; ++i) ASSERT_TRUE(queue.push_bounded("127.0.1." + std::to_string(i), [] {}));
  ASSERT_TRUE(queue.push_bounded("127.0.2.9", [] {}));
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"127.0.1.1", "127.0.2.9", "127.0.1.2", "127.0.1.3", "127.0.1.4",
                                                    "127.0.1.5"}));
}

TEST(PhotoJobQueue, WithinABlockAddressesTakeTurns) {
  PhotoJobQueue queue(100);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(queue.push_bounded("127.0.1.1", [] {}));
  ASSERT_TRUE(queue.push_bounded("127.0.1.2", [] {}));
  ASSERT_TRUE(queue.push_bounded("127.0.2.9", [] {}));
  EXPECT_EQ(drain(queue),
            (std::vector<std::string>{"127.0.1.1", "127.0.2.9", "127.0.1.2", "127.0.1.1", "127.0.1.1"}));
}

TEST(PhotoJobQueue, ABlockRunsNoMoreThanItsShareOfThreads) {
  PhotoJobQueue queue(100, 1);
  ASSERT_TRUE(queue.push_bounded("127.0.1.1", [] {}));
  ASSERT_TRUE(queue.push_bounded("127.0.1.2", [] {}));
  ASSERT_TRUE(queue.push_bounded("127.0.2.9", [] {}));
  auto first = queue.take();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->owner, "127.0.1.1");
  auto second = queue.take();
  ASSERT_TRUE(second) << "another block's photo is ready";
  EXPECT_EQ(second->owner, "127.0.2.9");
  EXPECT_FALSE(queue.ready()) << "127.0.1.2 is another address, but its block already prepares a photo";
  queue.finished("127.0.2.9");
  EXPECT_FALSE(queue.take());
  queue.finished("127.0.1.1");
  auto third = queue.take();
  ASSERT_TRUE(third);
  EXPECT_EQ(third->owner, "127.0.1.2");
}

TEST(PhotoJobQueue, OneBlockFillsAtMostHalfOfTheQueue) {
  PhotoJobQueue queue(8);
  EXPECT_EQ(queue.block_places(), 4u);
  for (int i = 1; i <= 4; ++i) ASSERT_TRUE(queue.push_bounded("127.0.1." + std::to_string(i), [] {}));
  EXPECT_TRUE(queue.full_for("127.0.1.200"));
  EXPECT_FALSE(queue.push_bounded("127.0.1.5", [] {})) << "a fifth address of the block";
  EXPECT_FALSE(queue.full());
  EXPECT_FALSE(queue.full_for("127.0.2.9"));
  EXPECT_TRUE(queue.push_bounded("127.0.2.9", [] {})) << "another block still has places";
  // A place taken to preparation is free again for the block.
  auto taken = queue.take();
  ASSERT_TRUE(taken);
  EXPECT_TRUE(queue.push_bounded("127.0.1.5", [] {}));
}

/// Jobs that hold their thread until the gate opens: at the end of the
/// test at the latest, so that a failed test does not hang in the worker's
/// destructor (declare the gate after the worker).
struct Gate {
  std::promise<void> promise;
  std::shared_future<void> opened = promise.get_future().share();
  bool is_open = false;
  std::function<void()> job(std::atomic<int>& started) {
    return [this, &started] {
      ++started;
      opened.wait();
    };
  }
  void open() {
    if (!std::exchange(is_open, true)) promise.set_value();
  }
  ~Gate() { open(); }
};

bool eventually(const std::function<bool()>& condition) {
  for (auto until = std::chrono::steady_clock::now() + 10s; std::chrono::steady_clock::now() < until;) {
    if (condition()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return condition();
}

TEST(PhotoWorker, AFullQueueRefusesUploadsButNotStoredAvatars) {
  std::atomic<int> started{0}, done{0};
  {
    PhotoWorker worker("", 1, 2);
    Gate gate;
    ASSERT_TRUE(worker.try_post("a", gate.job(started)));
    ASSERT_TRUE(eventually([&] { return started == 1; }));
    // One running, two waiting: the queue is full.
    EXPECT_TRUE(worker.try_post("b", [&] { ++done; }));
    EXPECT_TRUE(worker.try_post("c", [&] { ++done; }));
    EXPECT_TRUE(worker.full());
    EXPECT_FALSE(worker.try_post("d", [&] { ++done; }));
    EXPECT_GE(worker.expected_wait_seconds(), 1);
    worker.post([&] { ++done; });  // a stored avatar prepared again waits its turn
    gate.open();
    ASSERT_TRUE(eventually([&] { return done == 3; }));
    EXPECT_FALSE(worker.full());
    EXPECT_TRUE(worker.try_post("d", [&] { ++done; })) << "the queue takes uploads again";
  }  // the destructor runs what was queued
  EXPECT_EQ(done, 4);
}

TEST(PhotoWorker, ASecondThreadPreparesAnotherAddressesPhotoWhileTheFirstIsBusy) {
  std::atomic<int> started{0};
  PhotoWorker worker("", 2, 8);
  Gate gate;
  ASSERT_TRUE(worker.try_post("flood", gate.job(started)));
  ASSERT_TRUE(worker.try_post("flood", gate.job(started)));
  std::promise<std::thread::id> ann;
  ASSERT_TRUE(worker.try_post("ann", [&] { ann.set_value(std::this_thread::get_id()); }));
  auto ann_thread = ann.get_future();
  ASSERT_EQ(ann_thread.wait_for(10s), std::future_status::ready) << "ann's photo waited behind the flood";
  EXPECT_EQ(started, 1) << "the flood's second photo waits for its first";
  gate.open();
  ASSERT_TRUE(eventually([&] { return started == 2; }));
}

TEST(PhotoWorker, ABlockThatFloodsLeavesAThreadForAnotherBlock) {
  std::atomic<int> started{0};
  PhotoWorker worker("", 2, 8);
  Gate gate;
  // Slow photos from three addresses of one /24: with two threads, the
  // block prepares one at a time, and the other thread stays free.
  for (int i = 1; i <= 3; ++i) ASSERT_TRUE(worker.try_post("127.0.1." + std::to_string(i), gate.job(started)));
  ASSERT_TRUE(eventually([&] { return started == 1; }));
  std::promise<void> other;
  ASSERT_TRUE(worker.try_post("127.0.2.9", [&] { other.set_value(); }));
  ASSERT_EQ(other.get_future().wait_for(10s), std::future_status::ready) << "another block's photo waited";
  EXPECT_EQ(started, 1) << "the block's other addresses wait for its first photo";
  gate.open();
  ASSERT_TRUE(eventually([&] { return started == 3; }));
}

TEST(PhotoWorker, OneUploadAfterAnotherStaysOnTheFirstThread) {
  PhotoWorker worker("", 2, 8);
  std::mutex mutex;
  std::vector<std::thread::id> threads;
  for (int i = 0; i < 5; ++i) {
    std::promise<void> done;
    ASSERT_TRUE(worker.try_post("ann" + std::to_string(i), [&] {
      std::lock_guard lock(mutex);
      threads.push_back(std::this_thread::get_id());
      done.set_value();
    }));
    done.get_future().wait();
  }
  for (const auto& id : threads) EXPECT_EQ(id, threads.front()) << "a second model would load for nothing";
}

}  // namespace
}  // namespace fw::server
