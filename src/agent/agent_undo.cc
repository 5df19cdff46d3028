// Undo, as the session does it. Each reply that teaches the agent something
// opens a lesson (agent/lessons.h), which keeps the progress, the knowledge
// and the world as they were before it, and every write to the store until
// the next lesson. "undo" forgets the last lesson: the lessons revert those
// writes and restore the knowledge and the progress; the session says so
// and puts the world back by acting (the world changes only through the
// simulator), so the question that lesson answered comes again.
#include <algorithm>
#include <utility>

#include "agent/session.h"
#include "language/narration.h"
#include "language/narration_steps.h"
#include "search/iterative_deepening.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// Deep enough to undo any one action of the kitchen (at most: put down
// what is in hand, open, take out, close).
constexpr int kPutBackDepth = 4;

// The literals that turn `now` into `target`.
Goal difference(const State& now, const State& target) {
  std::vector<Literal> literals;
  for (const Fact& f : target.facts())
    if (!now.holds(f)) literals.push_back(Literal{f, true});
  for (const Fact& f : now.facts())
    if (!target.holds(f)) literals.push_back(Literal{f, false});
  return Goal(std::move(literals));
}

}  // namespace

void TaskLearningAgent::Session::begin_lesson(const std::string& reply) {
  if (!learning_ || !conversation_.with_teacher()) return;
  lessons_.begin(reply, progress_, agent_.knowledge_, world().state, simulator_.history().size());
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::undo() {
  auto undone = lessons_.undo(progress_, agent_.knowledge_);
  if (!undone) return stop(undone.error());
  if (!*undone) {
    say(language::nothing_to_undo(), Voice::kResponse);
    return {};
  }
  for (const ClassRule& rule : (*undone)->class_rules) sources_.remove_rule(rule);
  say(language::forgot_last((*undone)->reply), Voice::kResponse);
  put_world_back((*undone)->world, (*undone)->history);
  return tl::unexpected(Stop{});
}

void TaskLearningAgent::Session::put_world_back(const State& before, std::size_t history_size) {
  const Domain& domain = *world().domain;
  const std::vector<Action>& history = simulator_.history();
  if (history.size() <= history_size) return;
  std::vector<State> states{before};
  for (std::size_t i = history_size; i < history.size(); ++i) states.push_back(apply(domain, states.back(), history[i]));
  std::vector<Action> undoing;
  // Each action is undone in turn, latest first: each is a short search.
  for (std::size_t i = states.size() - 1; i-- > 0;) {
    Goal back = difference(world().state, states[i]);
    if (back.empty()) continue;
    SearchOptions options;
    options.max_depth = kPutBackDepth;
    PlanResult plan = find_plan(domain, *world().universe, world().state, back, options);
    bool done = plan.status == SearchStatus::kSolved;
    for (const Action& action : plan.plan) {
      if (!done || !execute(action)) {
        done = false;
        break;
      }
      undoing.push_back(action);
    }
    if (!done) {
      if (std::string back = language::put_back(world(), undoing, false); !back.empty()) say(back, Voice::kResponse);
      say(language::could_not_put_back(), Voice::kResponse);
      return;
    }
  }
  if (std::string back = language::put_back(world(), undoing, true); !back.empty()) say(back, Voice::kResponse);
}

}  // namespace apprentice
