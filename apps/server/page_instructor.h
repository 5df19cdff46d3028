// The teacher at the page: an Instructor whose answer() shows the question
// on the page (an event of the session) and blocks the agent's thread
// until the page posts the reply. It is a person (Instructor::is_person):
// the agent never gives up on it, and only the person ends the session
// ("quit", the page's Stop button) or the server does (cancel(): idle,
// shutdown).
//
// The agent lends the world for each call; the page is sent a drawing of
// it (world_view.h) with every question and every action, and what the
// agent knows with every question.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "instructor/instructor.h"
#include "session_events.h"

namespace apprentice::serve {

// What the page shows beside a question, asked for on the agent's thread
// while the agent waits (so that reading the agent's knowledge is safe).
struct PageViews {
  // What the agent knows: [{"what": "goal"|"rule"|"task", "text", "source",
  // "forget": the reply that forgets it, or null}].
  std::function<nlohmann::json()> knowledge;
  // How much of the world's intent holds: {"achieved", "total"}, or null.
  std::function<nlohmann::json(const World&)> progress;
};

class PageInstructor final : public Instructor {
 public:
  PageInstructor(SessionEvents& events, PageViews views) : events_(events), views_(std::move(views)) {}

  Result<std::string> answer(const Question& question, const World& world) override;
  void hear(std::string_view statement) override;
  void observe(const Action& action, const World& world) override;
  bool is_person() const override { return true; }

  // From an HTTP thread: the reply to the question whose event is numbered
  // `question`. Errors: kFailedPrecondition when that question is not the
  // one waiting (answered already, from another tab; or the agent is still
  // working), kCancelled when the session has ended.
  Status post(std::string reply, std::uint64_t question);
  // Ends the session from outside: the waiting answer() returns kCancelled,
  // and so does every later one.
  void cancel();

 private:
  void report_knowledge_changes(const nlohmann::json& knowledge);

  SessionEvents& events_;
  PageViews views_;
  std::mutex mutex_;
  std::condition_variable replied_;
  std::optional<std::uint64_t> waiting_;  // the event number of the question waiting
  std::optional<std::string> reply_;
  bool cancelled_ = false;
  std::set<std::string> known_;  // what the agent knew at the last question, as said
};

}  // namespace apprentice::serve
