#include "session_registry.h"

#include <random>

#include <fmt/format.h>

namespace apprentice::serve {

namespace {

// "30 minutes", "1 second"
std::string describe_duration(std::chrono::seconds duration) {
  long long s = duration.count();
  if (s % 60 == 0) return std::to_string(s / 60) + (s == 60 ? " minute" : " minutes");
  return std::to_string(s) + (s == 1 ? " second" : " seconds");
}

}  // namespace

std::string new_session_id() {
  std::random_device device;  // /dev/urandom
  std::string id;
  for (int i = 0; i < 4; ++i) id += fmt::format("{:08x}", device());
  return id;
}

Result<std::shared_ptr<TeachingSession>> SessionRegistry::start(SessionSetup setup) {
  {
    std::lock_guard lock(mutex_);
    int live = starting_;
    for (const auto& [id, session] : sessions_) live += session->ended() ? 0 : 1;
    if (live >= limits_.max_sessions)
      return make_error(ErrorCode::kUnavailable, "the server is already teaching " + std::to_string(live) +
                                                     " sessions, its limit (--max-sessions); try again when one ends");
    ++starting_;  // its place is held while it starts
  }
  if (setup.id.empty()) setup.id = new_session_id();
  // Built outside the lock: opening a store and making an agent take tens
  // of milliseconds, in which the other sessions' replies and events must
  // still find their sessions (find()).
  auto session = TeachingSession::start(std::move(setup));
  std::lock_guard lock(mutex_);
  --starting_;
  if (!session) return tl::unexpected(session.error());
  std::shared_ptr<TeachingSession> shared = std::move(*session);
  sessions_[shared->id()] = shared;
  return shared;
}

std::shared_ptr<TeachingSession> SessionRegistry::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto it = sessions_.find(id);
  return it == sessions_.end() ? nullptr : it->second;
}

void SessionRegistry::sweep(std::chrono::steady_clock::time_point now) {
  std::vector<std::shared_ptr<TeachingSession>> forgotten;  // destroyed outside the lock
  {
    std::lock_guard lock(mutex_);
    for (auto it = sessions_.begin(); it != sessions_.end();) {
      TeachingSession& session = *it->second;
      if (now - session.last_active() < limits_.idle) {
        ++it;
      } else if (!session.ended()) {
        session.end("No reply came for " + describe_duration(limits_.idle) + ", so this session has ended.");
        session.touch();  // forgotten after as long again
        ++it;
      } else {
        forgotten.push_back(std::move(it->second));
        it = sessions_.erase(it);
      }
    }
  }
}

void SessionRegistry::end_all() {
  std::map<std::string, std::shared_ptr<TeachingSession>> all;
  {
    std::lock_guard lock(mutex_);
    all.swap(sessions_);
  }
  for (auto& [id, session] : all) session->end("The server is stopping, so this session has ended.");
}

int SessionRegistry::teaching() const {
  std::lock_guard lock(mutex_);
  int live = 0;
  for (const auto& [id, session] : sessions_) live += session->ended() ? 0 : 1;
  return live;
}

}  // namespace apprentice::serve
