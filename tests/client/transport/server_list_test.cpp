#include "server_list.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(ServerList, OneUrlOrSeveralSeparatedByCommas) {
  std::vector<ServerUrl> servers;
  std::string error;
  ASSERT_TRUE(parse_server_list("ws://127.0.0.1:8080/", servers, error)) << error;
  ASSERT_EQ(servers.size(), 1u);
  EXPECT_EQ(servers[0].port, "8080");
  EXPECT_EQ(servers[0].text, "ws://127.0.0.1:8080/");
  ASSERT_TRUE(parse_server_list("ws://a:8080/, tcp://b:8081 ,ws://[::1]:9/ws", servers, error)) << error;
  ASSERT_EQ(servers.size(), 3u);
  EXPECT_EQ(servers[0].host, "a");
  EXPECT_EQ(servers[1].scheme, ServerUrl::Scheme::tcp);
  EXPECT_EQ(servers[1].text, "tcp://b:8081") << "the blanks around a URL are not part of it";
  EXPECT_EQ(servers[2].host, "::1");
  EXPECT_EQ(servers[2].path, "/ws");
}

TEST(ServerList, SaysWhichUrlIsWrong) {
  std::vector<ServerUrl> servers;
  std::string error;
  ASSERT_TRUE(parse_server_list("ws://a:8080/", servers, error));
  EXPECT_FALSE(parse_server_list("ws://a:8080/,http://b:8080/,ws://c:1/", servers, error));
  EXPECT_EQ(error.rfind("server 2 of 3: 'http://b:8080/': only ws:// and tcp://", 0), 0u) << error;
  EXPECT_FALSE(parse_server_list("ws://a:8080/,,ws://c:1/", servers, error));
  EXPECT_EQ(error, "server 2 of 3: nothing between the commas; list servers as ws://a:8080/,ws://b:8080/");
  EXPECT_FALSE(parse_server_list("ws://a:8080/,", servers, error));
  EXPECT_EQ(error.rfind("server 2 of 2: nothing between the commas", 0), 0u) << error;
  EXPECT_FALSE(parse_server_list("", servers, error));
  EXPECT_NE(error.find("no server URL"), std::string::npos) << error;
  EXPECT_FALSE(parse_server_list("ws://a:8080/,ws://a:8080/ws", servers, error));
  EXPECT_EQ(error, "server 2 of 2: 'ws://a:8080/ws' is listed twice; name each server once");
  std::string many;
  for (int i = 1; i <= 17; ++i) many += (i > 1 ? "," : "") + std::string("ws://h:") + std::to_string(i) + "/";
  EXPECT_FALSE(parse_server_list(many, servers, error));
  EXPECT_EQ(error, "at most 16 server URLs, not 17");
  ASSERT_EQ(servers.size(), 1u) << "a list that was refused leaves the servers as they were";
  EXPECT_EQ(servers[0].host, "a");
}

TEST(ServerList, SplitsAtCommasKeepingEmptyParts) {
  EXPECT_EQ(split_at_commas(" a , b,,c "), (std::vector<std::string>{"a", "b", "", "c"}));
  EXPECT_EQ(split_at_commas(""), (std::vector<std::string>{""}));
}

}  // namespace
}  // namespace fw::client
