// One person teaching one agent in one world, from the page: the agent runs
// on a thread of its own and asks the page (PageInstructor) for each reply.
// Sessions are independent: each has its own agent, simulator, dialogue,
// events and log; sessions on one knowledge store each open it themselves
// and follow its locking rules (knowledge/store.h).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "face/apprentice.h"
#include "page_instructor.h"
#include "session_events.h"
#include "world/scenario.h"

namespace apprentice::serve {

struct SessionSetup {
  std::string id;          // random, unguessable: it is the session's key
  std::string world_name;  // as the start screen offered it, or the uploaded world's name
  Scenario scenario;       // the agent is given only its world; the intent measures progress
  std::string store_name;  // empty: nothing is kept
  // The agent, as the server's flags say (server.h); its `knowledge` is the
  // location of the server's own store of that name, or empty, and its
  // `household` the server's --household.
  AgentSpec agent;
  std::optional<std::filesystem::path> log_path;  // under --log-dir, if given
};

class TeachingSession {
 public:
  // Opens the store and the log and starts the agent; the agent's first
  // question follows as an event. Errors: the store's (in use, damaged, not
  // a store) and the log's (kIo).
  static Result<std::unique_ptr<TeachingSession>> start(SessionSetup setup);
  // Ends the agent (what it learned is kept) and waits for its thread.
  ~TeachingSession();
  TeachingSession(const TeachingSession&) = delete;
  TeachingSession& operator=(const TeachingSession&) = delete;

  const std::string& id() const { return setup_.id; }
  const SessionEvents& events() const { return *events_; }
  // The teacher's reply to the question numbered `question`
  // (PageInstructor::post).
  Status reply(std::string text, std::uint64_t question) { return instructor_->post(std::move(text), question); }
  // Ends the session from outside (idle, shutdown): the agent stops as if
  // the teacher had said "quit". `why`, if given, is told to the page
  // first, unless the session has ended already.
  void end(const std::string& why = "");
  bool ended() const { return ended_; }

  // The page asked for or sent something.
  void touch() { last_active_ = std::chrono::steady_clock::now().time_since_epoch().count(); }
  // The last time the page asked for or sent anything, or the agent said
  // anything: a session is idle only while its question waits unanswered,
  // never while the agent works.
  std::chrono::steady_clock::time_point last_active() const {
    auto page = std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(last_active_.load()));
    return std::max(page, events_->last_append());
  }
  // {"id", "world", "store", "ended"}
  nlohmann::json description() const;

 private:
  TeachingSession(SessionSetup setup, std::unique_ptr<SessionEvents> events, std::unique_ptr<AgentSession> agent);
  void run();

  SessionSetup setup_;
  std::unique_ptr<SessionEvents> events_;
  // The agent, its store and all it uses; taught on the agent's thread, and
  // read there only (the page's views run while it waits for a reply).
  std::unique_ptr<AgentSession> agent_;
  std::unique_ptr<PageInstructor> instructor_;
  std::atomic<bool> ended_{false};
  std::atomic<std::chrono::steady_clock::rep> last_active_{0};
  std::thread thread_;
};

}  // namespace apprentice::serve
