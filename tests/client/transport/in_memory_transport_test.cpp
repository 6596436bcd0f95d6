#include "in_memory_transport.hpp"

#include <optional>
#include <string>

#include <boost/asio/error.hpp>
#include <gtest/gtest.h>

namespace fw::client {
namespace {

using Bytes = std::vector<std::uint8_t>;
using boost::system::error_code;

// What one read delivered.
struct ReadResult {
  error_code ec;
  Bytes message;
};

class InMemoryTransportTest : public ::testing::Test {
 protected:
  std::shared_ptr<MessageTransport> connected_transport() {
    auto transport = server_.transports()();
    std::optional<error_code> result;
    transport->connect(10, [&](error_code ec) { result = ec; });
    EXPECT_FALSE(result) << "completions are posted, never run inside the call";
    run();
    EXPECT_EQ(result, error_code{});
    return transport;
  }
  std::optional<ReadResult> read(MessageTransport& transport) {
    std::optional<ReadResult> result;
    transport.read([&](error_code ec, std::span<const std::uint8_t> message) {
      result = ReadResult{ec, Bytes(message.begin(), message.end())};
    });
    run();
    return result;
  }
  error_code write(MessageTransport& transport, Bytes message) {
    error_code result = boost::asio::error::would_block;
    transport.write(std::make_shared<const Bytes>(std::move(message)), [&](error_code ec) { result = ec; });
    run();
    return result;
  }
  void run() {
    io_.restart();
    io_.poll();
  }

  boost::asio::io_context io_;
  InMemoryServerEnd server_{io_};
};

TEST_F(InMemoryTransportTest, CarriesWholeMessagesBothWaysInOrder) {
  auto transport = connected_transport();
  EXPECT_TRUE(server_.connected());
  server_.send({1, 2, 3});
  server_.send({4});
  EXPECT_EQ(read(*transport)->message, (Bytes{1, 2, 3}));
  EXPECT_EQ(read(*transport)->message, (Bytes{4}));
  EXPECT_EQ(write(*transport, {9, 9}), error_code{});
  EXPECT_EQ(write(*transport, {8}), error_code{});
  EXPECT_EQ(server_.take_received(), (std::vector<Bytes>{{9, 9}, {8}}));
  EXPECT_TRUE(server_.take_received().empty()) << "taken out";
  EXPECT_EQ(transport->framing_bytes(100, true), 0u);
}

TEST_F(InMemoryTransportTest, AReadWaitsForTheNextMessage) {
  auto transport = connected_transport();
  std::optional<ReadResult> result;
  transport->read([&](error_code ec, std::span<const std::uint8_t> message) {
    result = ReadResult{ec, Bytes(message.begin(), message.end())};
  });
  run();
  EXPECT_FALSE(result);
  server_.send({5});
  run();
  ASSERT_TRUE(result);
  EXPECT_EQ(result->message, Bytes{5});
}

TEST_F(InMemoryTransportTest, ADropDeliversWhatWasSentThenEndOfFile) {
  auto transport = connected_transport();
  server_.send({1});
  server_.drop();
  EXPECT_FALSE(server_.connected());
  EXPECT_EQ(read(*transport)->message, Bytes{1});
  EXPECT_EQ(read(*transport)->ec, boost::asio::error::eof);
  EXPECT_EQ(write(*transport, {2}), boost::asio::error::broken_pipe);
  EXPECT_FALSE(server_.closed_by_client());
}

TEST_F(InMemoryTransportTest, ClosingAbortsTheOutstandingRead) {
  auto transport = connected_transport();
  std::optional<error_code> result;
  transport->read([&](error_code ec, std::span<const std::uint8_t>) { result = ec; });
  transport->close();
  run();
  EXPECT_EQ(result, boost::asio::error::operation_aborted);
  EXPECT_TRUE(server_.closed_by_client());
  server_.send({1});  // too late: nobody reads
  EXPECT_EQ(read(*transport)->ec, boost::asio::error::operation_aborted);
}

TEST_F(InMemoryTransportTest, ARefusedConnectionFailsToConnect) {
  server_.refuse_connections(boost::asio::error::connection_refused);
  auto transport = server_.transports()();
  std::optional<error_code> result;
  transport->connect(10, [&](error_code ec) { result = ec; });
  run();
  EXPECT_EQ(result, boost::asio::error::connection_refused);
  EXPECT_FALSE(server_.connected());
  server_.refuse_connections({});
  connected_transport();
  EXPECT_EQ(server_.attempts(), 2);
}

TEST_F(InMemoryTransportTest, TheServerTalksToTheNewestConnection) {
  auto first = connected_transport();
  auto second = connected_transport();
  server_.send({7});
  EXPECT_EQ(read(*second)->message, Bytes{7});
  std::optional<ReadResult> on_first;
  first->read([&](error_code ec, std::span<const std::uint8_t> m) { on_first = ReadResult{ec, Bytes(m.begin(), m.end())}; });
  run();
  EXPECT_FALSE(on_first) << "the old connection got nothing";
}

}  // namespace
}  // namespace fw::client
