#include "delivery_batch.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

namespace fw::server {

namespace net = boost::asio;

namespace {
thread_local DeliveryBatch* open_batch = nullptr;
}

DeliveryBatch::DeliveryBatch() : outer_(open_batch) {
  if (!outer_) open_batch = this;
}

DeliveryBatch::~DeliveryBatch() {
  if (outer_) return;
  open_batch = nullptr;
  if (writers_.empty()) return;
  // One job on the first connection's strand; from there each connection's
  // writing is dispatched to its own strand, which runs it in place when no
  // other thread holds that strand (no queueing, no wake-up).
  const auto first = writers_.front()->strand();
  net::post(first, [writers = std::move(writers_)]() mutable {
    for (auto& writer : writers) {
      const auto& strand = writer->strand();
      net::dispatch(strand, [writer = std::move(writer)] { writer->write_delivered(); });
    }
  });
}

DeliveryBatch* DeliveryBatch::open() {
  return open_batch;
}

void DeliveryBatch::enlist(std::shared_ptr<BatchedWriter> writer) {
  if (outer_) return outer_->enlist(std::move(writer));
  if (writers_.empty()) writers_.reserve(kTypicalWriters);
  writers_.push_back(std::move(writer));
}

}  // namespace fw::server
