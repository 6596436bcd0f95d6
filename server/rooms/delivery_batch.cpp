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
  if (entries_.empty()) return;
  // One job on the first connection's strand; from there each connection's
  // writing is dispatched to its own strand, which runs it in place when no
  // other thread holds that strand (no queueing, no wake-up).
  auto first = entries_.front().strand;
  net::post(first, [entries = std::move(entries_)]() mutable {
    for (auto& entry : entries) {
      net::dispatch(entry.strand, [writer = std::move(entry.writer)] { writer->write_delivered(); });
    }
  });
}

DeliveryBatch* DeliveryBatch::open() {
  return open_batch;
}

void DeliveryBatch::enlist(net::any_io_executor strand, std::shared_ptr<BatchedWriter> writer) {
  if (outer_) return outer_->enlist(std::move(strand), std::move(writer));
  if (entries_.empty()) entries_.reserve(kTypicalEntries);
  entries_.push_back({std::move(strand), std::move(writer)});
}

}  // namespace fw::server
