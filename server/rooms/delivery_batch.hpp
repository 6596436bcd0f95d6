#pragma once
// The messages of one room tick, handed to the I/O threads in one go.
//
// A room tick gives each of its subscribers a message or two (its room
// frame). Posted one by one to each connection's strand, every message
// locks the I/O pool's queue and often wakes a sleeping I/O thread (a
// futex or an epoll_ctl, then a context switch): at 100 rooms of 10, 30,000
// wake-ups a second, a tenth of the server's time in a profile of
// `facewire-bench fanout --rooms 100`. While a DeliveryBatch is open on a
// thread (Room::end_tick opens one around its tick), a connection that
// takes part (ClientSession) keeps the message in its own queue and enlists
// its writing here; when the batch closes it posts one job to the I/O pool,
// which runs each enlisted connection's writing on that connection's
// strand (at once where the strand is free).
//
// A connection's messages still go out in the order it was given them:
// the batch only decides when the I/O threads hear of them.
// Not thread-safe: a batch belongs to the thread that opened it.
#include <cstddef>
#include <memory>
#include <vector>

#include <boost/asio/any_io_executor.hpp>

namespace fw::server {

/// A connection that takes part: it keeps what it is given and writes it
/// when told to, on its strand.
class BatchedWriter {
 public:
  virtual const boost::asio::any_io_executor& strand() const = 0;
  virtual void write_delivered() = 0;

 protected:
  ~BatchedWriter() = default;
};

class DeliveryBatch {
 public:
  /// Opens a batch on this thread; inside another one it adds to the outer
  /// batch, which alone posts.
  DeliveryBatch();
  /// Posts what was enlisted (if this is the outermost batch).
  ~DeliveryBatch();
  DeliveryBatch(const DeliveryBatch&) = delete;
  DeliveryBatch& operator=(const DeliveryBatch&) = delete;

  /// The batch open on this thread, or null.
  static DeliveryBatch* open();

  /// `writer->write_delivered()` runs once on its strand after the batch closes.
  void enlist(std::shared_ptr<BatchedWriter> writer);

  /// Room for a room of this many subscribers before the writers grow (an
  /// allocation per doubling, every tick: they go with the job). Small, so
  /// that it is no request malloc serves by sorting its free lists first.
  static constexpr std::size_t kTypicalWriters = 16;

 private:
  DeliveryBatch* outer_;
  std::vector<std::shared_ptr<BatchedWriter>> writers_;
};

}  // namespace fw::server
