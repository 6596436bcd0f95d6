// A room tick's messages reach the I/O threads in one post (DeliveryBatch),
// and each connection still writes what it was given in order, batched or
// not, before a close that follows it.
#include "delivery_batch.hpp"

#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "in_memory_session.hpp"

namespace fw::server {
namespace {

namespace net = boost::asio;
using test::eventually;
using test::InMemoryServer;

constexpr int kConnections = 10;

/// Notes in `ran` when told to write.
class NotingWriter final : public BatchedWriter {
 public:
  NotingWriter(net::any_io_executor strand, std::vector<int>& ran, int id)
      : strand_(std::move(strand)), ran_(ran), id_(id) {}
  const net::any_io_executor& strand() const override { return strand_; }
  void write_delivered() override { ran_.push_back(id_); }

 private:
  net::any_io_executor strand_;
  std::vector<int>& ran_;
  int id_;
};

std::vector<net::any_io_executor> strands_of(net::io_context& io) {
  std::vector<net::any_io_executor> strands;
  for (int i = 0; i < kConnections; ++i) strands.emplace_back(net::make_strand(io));
  return strands;
}

TEST(DeliveryBatch, PostsATicksWritesAsOneJobThatRunsThemInOrder) {
  net::io_context io;
  const auto strands = strands_of(io);
  std::vector<int> ran;
  {
    const DeliveryBatch batch;
    ASSERT_EQ(DeliveryBatch::open(), &batch);
    for (int i = 0; i < kConnections; ++i) {
      DeliveryBatch::open()->enlist(std::make_shared<NotingWriter>(strands[i], ran, i));
    }
    EXPECT_EQ(io.poll(), 0u) << "nothing is posted while the batch is open";
    io.restart();
  }
  EXPECT_EQ(DeliveryBatch::open(), nullptr);
  EXPECT_EQ(io.poll(), 1u) << "one job for every connection of the tick";
  ASSERT_EQ(ran.size(), static_cast<std::size_t>(kConnections));
  for (int i = 0; i < kConnections; ++i) EXPECT_EQ(ran[i], i);

  // Without a batch, as before: one job a connection.
  io.restart();
  for (int i = 0; i < kConnections; ++i) net::post(strands[i], [] {});
  EXPECT_EQ(io.poll(), static_cast<std::size_t>(kConnections));
}

TEST(DeliveryBatch, AnInnerBatchAddsToTheOuterOneAndOnlyTheOuterPosts) {
  net::io_context io;
  const auto strands = strands_of(io);
  std::vector<int> ran;
  {
    const DeliveryBatch outer;
    {
      DeliveryBatch inner;
      EXPECT_EQ(DeliveryBatch::open(), &outer);
      inner.enlist(std::make_shared<NotingWriter>(strands[0], ran, 1));
    }
    EXPECT_EQ(io.poll(), 0u) << "the inner batch closing posts nothing";
    io.restart();
    EXPECT_EQ(DeliveryBatch::open(), &outer);
  }
  EXPECT_EQ(io.poll(), 1u);
  EXPECT_EQ(ran, std::vector<int>{1});
}

TEST(DeliveryBatch, BelongsToTheThreadThatOpenedIt) {
  DeliveryBatch batch;
  DeliveryBatch* seen = &batch;
  std::thread([&seen] { seen = DeliveryBatch::open(); }).join();
  EXPECT_EQ(seen, nullptr);
}

SharedBytes bytes_of(std::size_t size, std::uint8_t fill) { return share(std::vector<std::uint8_t>(size, fill)); }

TEST(DeliveryBatch, ASessionWritesWhatItIsGivenInOrderBatchedOrNot) {
  InMemoryServer server;
  auto peer = server.connect();
  InMemorySession& session = peer->session();
  {
    const DeliveryBatch batch;
    session.deliver(bytes_of(10, 1));
    session.deliver(bytes_of(10, 2));
  }
  session.deliver(bytes_of(10, 3));
  {
    const DeliveryBatch batch;
    session.deliver(bytes_of(10, 4));
  }
  std::vector<SharedBytes> written;
  ASSERT_TRUE(eventually([&] {
    for (auto& message : session.take_written()) written.push_back(std::move(message));
    return written.size() == 4;
  }));
  for (std::uint8_t i = 0; i < 4; ++i) EXPECT_EQ(written[i]->front(), i + 1);
  EXPECT_EQ(session.queued_bytes(), 0u);
}

TEST(DeliveryBatch, AMessageDeliveredBeforeACloseGoesOutBeforeTheClosingMessage) {
  InMemoryServer server;
  auto peer = server.connect();
  {
    // The close is posted at once, the batch's job only when it closes:
    // the session takes the message it was given first all the same.
    const DeliveryBatch batch;
    peer->session().deliver(encode_shared(codec::Chat{7, "last words"}));
    peer->session().close(codec::CloseCode::normal, "bye");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(peer->read_until_closed());
  peer->read();
  ASSERT_EQ(peer->chat.size(), 1u);
  EXPECT_EQ(peer->chat[0].text, "last words");
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->reason, "bye");
}

}  // namespace
}  // namespace fw::server
