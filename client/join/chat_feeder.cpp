#include "chat_feeder.hpp"

#include <poll.h>
#include <unistd.h>

#include <utility>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

// How often a waiting feeder looks whether it should stop.
constexpr auto kPoll = std::chrono::milliseconds(50);

}  // namespace

ChatFeeder::ChatFeeder(std::vector<ScriptedLine> script, JoinedAt joined_at, Say say)
    : say_(std::move(say)),
      thread_([this, script = std::move(script), joined_at = std::move(joined_at)]() mutable {
        play_script(std::move(script), std::move(joined_at));
      }) {}

ChatFeeder::ChatFeeder(int fd, Say say, Tell tell)
    : say_(std::move(say)), thread_([this, fd, tell = std::move(tell)] { read_lines(fd, tell); }) {}

ChatFeeder::~ChatFeeder() { stop(); }

void ChatFeeder::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

void ChatFeeder::play_script(std::vector<ScriptedLine> script, JoinedAt joined_at) {
  std::optional<Clock::time_point> joined;
  for (const ScriptedLine& line : script) {
    for (;;) {
      if (stopping_) return;
      if (!joined) joined = joined_at();
      if (joined && Clock::now() >= *joined + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(line.at_s)))
        break;
      std::this_thread::sleep_for(kPoll);
    }
    say_(line.text);
    ++sent_;
  }
}

void ChatFeeder::read_lines(int fd, Tell tell) {
  std::string pending;
  bool skipping = false;  // the rest of a line already refused as too long
  const auto finish_line = [&](std::string line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (std::exchange(skipping, false) || line.empty()) return;
    if (line.size() > codec::kMaxChatBytes) {
      tell("chat line not sent: it holds " + std::to_string(line.size()) + " bytes, at most " +
           std::to_string(codec::kMaxChatBytes) + " go in one line");
      return;
    }
    say_(std::move(line));
    ++sent_;
  };
  char buffer[4096];
  for (;;) {
    // poll() with a time-out, so that stop() is not held up by a terminal
    // nobody types into.
    pollfd readable{fd, POLLIN, 0};
    const int ready = ::poll(&readable, 1, static_cast<int>(kPoll.count()));
    if (stopping_) return;
    if (ready <= 0) continue;
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got <= 0) break;  // the end of the input (or an error): nothing more to send
    pending.append(buffer, static_cast<std::size_t>(got));
    for (std::size_t end; (end = pending.find('\n')) != std::string::npos;) {
      finish_line(pending.substr(0, end));
      pending.erase(0, end + 1);
    }
    // A line that outgrows any chat line before it ends is refused now,
    // not held in memory to its end.
    if (!skipping && pending.size() > codec::kMaxChatBytes) {
      tell("chat line not sent: more than " + std::to_string(codec::kMaxChatBytes) + " bytes without a line end");
      skipping = true;
    }
    if (skipping) pending.clear();
  }
  finish_line(std::move(pending));
}

}  // namespace fw::client
