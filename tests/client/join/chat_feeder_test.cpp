#include "chat_feeder.hpp"

#include <mutex>
#include <thread>

#include <gtest/gtest.h>
#include <unistd.h>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

using namespace std::chrono_literals;

// What the feeder handed on, from its thread.
struct Said {
  std::mutex mutex;
  std::vector<std::pair<std::string, ChatFeeder::Clock::time_point>> lines;
  std::vector<std::string> told;
  std::size_t count() {
    std::lock_guard lock(mutex);
    return lines.size();
  }
};

bool wait_for(Said& said, std::size_t n) {
  for (int i = 0; i < 300 && said.count() < n; ++i) std::this_thread::sleep_for(10ms);
  return said.count() >= n;
}

TEST(ChatFeeder, LinesTypedAreSentAsTheyCome) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  Said said;
  ChatFeeder feeder(
      fds[0],
      [&](std::string line) {
        std::lock_guard lock(said.mutex);
        said.lines.emplace_back(std::move(line), ChatFeeder::Clock::now());
      },
      [&](const std::string& message) {
        std::lock_guard lock(said.mutex);
        said.told.push_back(message);
      });
  const std::string first = "hello\r\n\n";
  ASSERT_EQ(::write(fds[1], first.data(), first.size()), static_cast<ssize_t>(first.size()));
  ASSERT_TRUE(wait_for(said, 1));
  const std::string too_long(codec::kMaxChatBytes + 1, 'x');
  const std::string rest = too_long + "\nsecond li";
  ASSERT_EQ(::write(fds[1], rest.data(), rest.size()), static_cast<ssize_t>(rest.size()));
  const std::string end = "ne\nlast without an end";
  ASSERT_EQ(::write(fds[1], end.data(), end.size()), static_cast<ssize_t>(end.size()));
  ::close(fds[1]);
  ASSERT_TRUE(wait_for(said, 3));
  feeder.stop();
  ::close(fds[0]);
  std::lock_guard lock(said.mutex);
  ASSERT_EQ(said.lines.size(), 3u);
  EXPECT_EQ(said.lines[0].first, "hello");
  EXPECT_EQ(said.lines[1].first, "second line");
  EXPECT_EQ(said.lines[2].first, "last without an end");
  ASSERT_EQ(said.told.size(), 1u);
  EXPECT_NE(said.told[0].find("not sent"), std::string::npos);
  EXPECT_EQ(feeder.sent(), 3);
}

TEST(ChatFeeder, AScriptWaitsForTheWelcomeAndKeepsItsTimes) {
  std::atomic<bool> joined{false};
  const auto start = ChatFeeder::Clock::now();
  ChatFeeder::Clock::time_point joined_at{};
  Said said;
  ChatFeeder feeder(
      {{0.0, "at once"}, {0.3, "a moment later"}},
      [&]() -> std::optional<ChatFeeder::Clock::time_point> {
        if (!joined) return std::nullopt;
        return joined_at;
      },
      [&](std::string line) {
        std::lock_guard lock(said.mutex);
        said.lines.emplace_back(std::move(line), ChatFeeder::Clock::now());
      });
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(said.count(), 0u) << "nothing before the welcome";
  joined_at = ChatFeeder::Clock::now();
  joined = true;
  ASSERT_TRUE(wait_for(said, 2));
  std::lock_guard lock(said.mutex);
  EXPECT_GE(said.lines[0].second, joined_at);
  EXPECT_GE(said.lines[1].second - joined_at, 300ms);
  EXPECT_LT(said.lines[1].second - start, 3s);
}

TEST(ChatFeeder, StopEndsAWaitingFeederAtOnce) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ChatFeeder feeder(fds[0], [](std::string) {}, [](const std::string&) {});
  const auto start = ChatFeeder::Clock::now();
  feeder.stop();
  EXPECT_LT(ChatFeeder::Clock::now() - start, 1s);
  ::close(fds[0]);
  ::close(fds[1]);
}

}  // namespace
}  // namespace fw::client
