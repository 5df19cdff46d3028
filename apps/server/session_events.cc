#include "session_events.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "util/json.h"

namespace apprentice::serve {

namespace {

// "2026-12-01T09:30:12.345Z"
std::string utc_now() {
  auto now = std::chrono::system_clock::now();
  auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm tm{};
  gmtime_r(&t, &tm);
  return fmt::format("{:%Y-%m-%dT%H:%M:%S}.{:03d}Z", tm, static_cast<int>(ms));
}

}  // namespace

Result<std::unique_ptr<SessionEvents>> SessionEvents::open(std::optional<std::filesystem::path> log_path) {
  std::unique_ptr<SessionEvents> events(new SessionEvents(log_path));
  if (log_path) {
    events->log_file_.open(*log_path, std::ios::binary | std::ios::app);
    if (!events->log_file_) return make_error(ErrorCode::kIo, log_path->string() + ": cannot be written");
  }
  return events;
}

std::uint64_t SessionEvents::append(nlohmann::json body) {
  nlohmann::json logged = body;
  logged.erase("world");
  std::string line;
  std::uint64_t seq = 0;
  {
    std::lock_guard lock(mutex_);
    seq = events_.size() + 1;
    nlohmann::json stamped{{"seq", seq}, {"time", utc_now()},
                           {"ms", std::chrono::duration_cast<std::chrono::milliseconds>(elapsed()).count()}};
    stamped.update(logged);
    line = dump_json(stamped);
    log_lines_.push_back(line);
    if (log_file_.is_open()) {
      log_file_ << line << '\n';
      log_file_.flush();
    }
    if (body.contains("world")) {
      if (last_world_) events_[*last_world_].body.erase("world");
      last_world_ = events_.size();
    }
    events_.push_back(Event{seq, std::move(body)});
    last_append_ = std::chrono::steady_clock::now();
  }
  changed_.notify_all();
  return seq;
}

void SessionEvents::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

std::vector<Event> SessionEvents::after(std::uint64_t after, std::chrono::milliseconds wait, bool* closed) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, wait, [&] { return events_.size() > after || closed_; });
  std::vector<Event> out;
  for (std::size_t i = after; i < events_.size(); ++i) out.push_back(events_[i]);
  if (closed) *closed = closed_;
  return out;
}

std::uint64_t SessionEvents::last_seq() const {
  std::lock_guard lock(mutex_);
  return events_.size();
}

std::string SessionEvents::log_text() const {
  std::lock_guard lock(mutex_);
  std::string text;
  for (const std::string& line : log_lines_) text += line + "\n";
  return text;
}

std::chrono::steady_clock::time_point SessionEvents::last_append() const {
  std::lock_guard lock(mutex_);
  return last_append_;
}

std::chrono::milliseconds SessionEvents::elapsed() const {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start_);
}

}  // namespace apprentice::serve
