#pragma once
// Sends a person's chat lines while `join` runs, on a thread of its own:
// either a script's timed lines (chat_script.hpp), each at its time after
// the first welcome, or the lines of a file descriptor (standard input) as
// they are typed. Lines typed before the welcome go out with it (the
// session keeps them). Stops at stop() or destruction; a line the person
// cannot send (too long) is told, not sent.
#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "chat_script.hpp"

namespace fw::client {

class ChatFeeder {
 public:
  using Clock = std::chrono::steady_clock;
  /// Hands a line to the session (thread-safe: SessionThread::say).
  using Say = std::function<void(std::string line)>;
  /// When the first welcome came, if it has.
  using JoinedAt = std::function<std::optional<Clock::time_point>()>;
  /// Tells the person something (a line not sent).
  using Tell = std::function<void(const std::string& message)>;

  /// The script's lines, each `at_s` after joining.
  ChatFeeder(std::vector<ScriptedLine> script, JoinedAt joined_at, Say say);
  /// Every line read from `fd` until its end.
  ChatFeeder(int fd, Say say, Tell tell);
  ~ChatFeeder();
  ChatFeeder(const ChatFeeder&) = delete;
  ChatFeeder& operator=(const ChatFeeder&) = delete;

  void stop();
  /// How many lines were handed to the session so far.
  int sent() const { return sent_; }

 private:
  void play_script(std::vector<ScriptedLine> script, JoinedAt joined_at);
  void read_lines(int fd, Tell tell);

  Say say_;
  std::atomic<bool> stopping_{false};
  std::atomic<int> sent_{0};
  std::thread thread_;
};

}  // namespace fw::client
