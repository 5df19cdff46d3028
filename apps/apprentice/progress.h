// The progress line of long runs: on a terminal, `experiment` and `teach`
// show on stderr which condition runs, which object the LLM is asked
// about, how many LLM calls so far, and the time elapsed, redrawn in place
// every second. Nothing is drawn when stderr is not a terminal, or when the
// user asked for --json or --quiet.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "experiment/progress.h"

namespace apprentice::cli {

class TerminalProgress final : public ExperimentObserver {
 public:
  enum class Mode {
    kWholeRun,     // experiment: the line stays while the run goes on
    kLlmQueries,   // teach: the line shows only while an LLM query is out
  };

  // Draws on `stream` only when `wanted` and `stream` is a terminal.
  TerminalProgress(std::FILE* stream, bool wanted, Mode mode);
  // Erases the line.
  ~TerminalProgress() override;
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  bool active() const { return active_; }

  void condition_started(const std::string& condition, int index, int count) override;
  void llm_query_started(const llm::QueryAbout& about, int calls) override;
  void llm_query_finished(const llm::QueryAbout& about, int calls) override;

  // The line as it would be drawn now (for tests).
  std::string line() const;

 private:
  void tick();
  void draw_locked();
  void erase_locked();
  std::string line_locked() const;

  std::FILE* stream_;
  const bool active_;
  const Mode mode_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool drawn_ = false;
  bool querying_ = false;
  std::string condition_;
  int index_ = 0, count_ = 0;
  int calls_ = 0;      // LLM calls of this condition
  std::string about_;  // what the current or last query is about
  std::thread ticker_;
};

}  // namespace apprentice::cli
