#include "server_url.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(ServerUrl, ReadsWebSocketAndTcpUrls) {
  ServerUrl url;
  std::string error;
  ASSERT_TRUE(parse_server_url("ws://127.0.0.1:8080/", url, error)) << error;
  EXPECT_EQ(url.scheme, ServerUrl::Scheme::websocket);
  EXPECT_EQ(url.host, "127.0.0.1");
  EXPECT_EQ(url.port, "8080");
  EXPECT_EQ(url.path, "/");
  ASSERT_TRUE(parse_server_url("ws://example.org:80/ws", url, error)) << error;
  EXPECT_EQ(url.path, "/ws");
  ASSERT_TRUE(parse_server_url("ws://localhost:9", url, error)) << error;
  EXPECT_EQ(url.path, "/");
  ASSERT_TRUE(parse_server_url("tcp://10.0.0.2:8081", url, error)) << error;
  EXPECT_EQ(url.scheme, ServerUrl::Scheme::tcp);
  EXPECT_EQ(url.port, "8081");
  ASSERT_TRUE(parse_server_url("tcp://[::1]:8081/", url, error)) << error;
  EXPECT_EQ(url.host, "::1");
}

TEST(ServerUrl, RefusesWhatItCannotConnectToAndSaysWhatAUrlLooksLike) {
  ServerUrl url;
  std::string error;
  for (const char* bad : {"127.0.0.1:8080", "ws://127.0.0.1/", "ws://:80/", "tcp://host:0", "tcp://host:70000",
                          "tcp://host:80/path", "wss://host:443/", "http://host:80/", "ws://[::1]/", "ws://host:8o/"}) {
    error.clear();
    EXPECT_FALSE(parse_server_url(bad, url, error)) << bad;
    EXPECT_NE(error.find("ws://"), std::string::npos) << bad << ": " << error;
  }
}

}  // namespace
}  // namespace fw::client
