// What happened in one teaching session, in order: the agent's questions
// and statements, the teacher's replies, the actions, what was learned and
// the end. The page is sent these events (Server-Sent Events, each with its
// number, so that a reload or a reconnect asks for what it has not seen);
// the study log keeps the same events as JSON lines, with times.
//
// Thread-safe: the agent's thread appends, HTTP threads read and wait.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace apprentice::serve {

struct Event {
  std::uint64_t seq = 0;  // 1, 2, 3, ...
  nlohmann::json body;    // {"type": "question"|"say"|"reply"|"action"|"learned"|"end", ...}
};

class SessionEvents {
 public:
  // `log_path`: the study log's file, written a line at a time and flushed
  // (none: the log is kept in memory only, for download).
  static Result<std::unique_ptr<SessionEvents>> open(std::optional<std::filesystem::path> log_path);

  // Appends an event, logs it, and wakes whoever waits. A body with a
  // "world" (the world as drawn) takes it from the event before that had
  // one: a page catching up draws only the latest world, so older ones
  // need not be kept or sent. The log never holds worlds.
  std::uint64_t append(nlohmann::json body);
  // Marks the end: after the events already appended there are no more.
  void close();

  // The events numbered above `after`, waiting up to `wait` for one when
  // there are none yet. `*closed`: whether no more will come.
  std::vector<Event> after(std::uint64_t after, std::chrono::milliseconds wait, bool* closed) const;
  std::uint64_t last_seq() const;
  // The study log so far: one JSON object a line.
  std::string log_text() const;
  // The time since the first event.
  std::chrono::milliseconds elapsed() const;
  // When the last event was appended (the session's start before any).
  std::chrono::steady_clock::time_point last_append() const;

 private:
  explicit SessionEvents(std::optional<std::filesystem::path> log_path) : log_path_(std::move(log_path)) {}

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::vector<Event> events_;
  std::optional<std::size_t> last_world_;  // the index of the last event with a world
  bool closed_ = false;
  std::vector<std::string> log_lines_;
  std::optional<std::filesystem::path> log_path_;
  std::ofstream log_file_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_append_ = start_;
};

}  // namespace apprentice::serve
