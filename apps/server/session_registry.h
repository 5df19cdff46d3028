// The sessions a server holds, by id, within its limits: at most
// max_sessions teaching at once, and a session that hears nothing from its
// page for the idle time is ended (what it taught is kept), then forgotten
// after as long again (its log stays in --log-dir).
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "server.h"
#include "teaching_session.h"

namespace apprentice::serve {

// 32 hex digits from the system's random source: a session's id is its key.
std::string new_session_id();

class SessionRegistry {
 public:
  explicit SessionRegistry(ServeLimits limits) : limits_(limits) {}
  ~SessionRegistry() { end_all(); }

  // Starts a session (its id is made here). Errors: kUnavailable when
  // max_sessions are teaching; TeachingSession::start's.
  Result<std::shared_ptr<TeachingSession>> start(SessionSetup setup);
  // Null when there is no such session (never was, or forgotten).
  std::shared_ptr<TeachingSession> find(const std::string& id) const;
  void sweep(std::chrono::steady_clock::time_point now);
  // Ends every session and forgets them (at shutdown).
  void end_all();
  int teaching() const;

 private:
  ServeLimits limits_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<TeachingSession>> sessions_;
  int starting_ = 0;  // sessions being started, outside the lock
};

}  // namespace apprentice::serve
