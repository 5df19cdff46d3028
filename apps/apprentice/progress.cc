#include "progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <fmt/format.h>

namespace apprentice::cli {

namespace {

// Redraws at this interval; the first draw waits as long, so that quick
// runs print nothing at all.
constexpr auto kTick = std::chrono::milliseconds(500);

std::size_t terminal_width(std::FILE* stream) {
  winsize size{};
  if (ioctl(fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col > 10) return size.ws_col;
  return 80;
}

std::string describe_query(const llm::QueryAbout& about) {
  std::string object = about.object_category.empty() ? "the task" : "the " + about.object_category;
  if (!about.place.empty()) object += " on the " + about.place;
  switch (about.kind) {
    case llm::QueryKind::kGoal: return "a goal for " + object;
    case llm::QueryKind::kActionWord:
    case llm::QueryKind::kAction: return "the next step for " + object;
    case llm::QueryKind::kSummary: return "the rule of the examples taught";
    case llm::QueryKind::kPlacement: return "where " + std::to_string(about.objects.size()) + " things go";
  }
  return object;
}

}  // namespace

TerminalProgress::TerminalProgress(std::FILE* stream, bool wanted, Mode mode)
    : stream_(stream), active_(wanted && stream != nullptr && isatty(fileno(stream))), mode_(mode) {
  if (active_) ticker_ = std::thread([this] { tick(); });
}

TerminalProgress::~TerminalProgress() {
  if (!active_) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    erase_locked();
  }
  wake_.notify_all();
  ticker_.join();
}

void TerminalProgress::condition_started(const std::string& condition, int index, int count) {
  std::lock_guard lock(mutex_);
  condition_ = condition;
  index_ = index;
  count_ = count;
  calls_ = 0;
  about_.clear();
}

void TerminalProgress::llm_query_started(const llm::QueryAbout& about, int calls) {
  std::lock_guard lock(mutex_);
  querying_ = true;
  calls_ = calls;
  about_ = describe_query(about);
}

void TerminalProgress::llm_query_finished(const llm::QueryAbout& about, int calls) {
  (void)about;
  std::lock_guard lock(mutex_);
  querying_ = false;
  calls_ = calls;
  if (mode_ == Mode::kLlmQueries) erase_locked();
}

std::string TerminalProgress::line() const {
  std::lock_guard lock(mutex_);
  return line_locked();
}

std::string TerminalProgress::line_locked() const {
  // What matters most first, so that a narrow terminal cuts the least of it:
  // "inst+llm (2 of 6): 14 LLM calls, 35 s; asking the LLM for a goal for the ketchup on the table"
  auto elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  std::string text;
  if (!condition_.empty()) text = fmt::format("{} ({} of {}): ", condition_, index_ + 1, count_);
  text += fmt::format("{} LLM call{}, {:.0f} s", calls_, calls_ == 1 ? "" : "s", elapsed);
  if (!about_.empty()) text += fmt::format("; {} {}", querying_ ? "asking the LLM for" : "asked the LLM for", about_);
  return text;
}

void TerminalProgress::draw_locked() {
  std::string text = line_locked();
  std::size_t width = terminal_width(stream_) - 1;
  if (text.size() > width) text = text.substr(0, width - 3) + "...";
  // \r and "erase to the end of the line", so that a shorter line leaves
  // nothing of a longer one behind.
  std::fprintf(stream_, "\r%s\x1b[K", text.c_str());
  std::fflush(stream_);
  drawn_ = true;
}

void TerminalProgress::erase_locked() {
  if (!drawn_) return;
  std::fputs("\r\x1b[K", stream_);
  std::fflush(stream_);
  drawn_ = false;
}

void TerminalProgress::tick() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, kTick, [this] { return stopping_; })) {
    if (mode_ == Mode::kWholeRun || querying_) draw_locked();
  }
}

}  // namespace apprentice::cli
