// Undo, as the session does it. Each reply that teaches the agent something
// opens a lesson (agent/lessons.h), which keeps the progress, the knowledge
// and the world as they were before it, and every write to the store until
// the next lesson. "undo" forgets the last lesson: the lessons revert those
// writes and restore the knowledge and the progress; the session says so
// and puts the world back by acting (the world changes only through the
// simulator), so the question that lesson answered comes again.
#include <algorithm>
#include <set>
#include <utility>

#include "agent/session.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "language/narration_steps.h"
#include "search/iterative_deepening.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// Deep enough to undo any one action of the kitchen (at most: put down
// what is in hand, open, take out, close).
constexpr int kPutBackDepth = 4;

// Whether `fact` is about one of `objects`; a fact about nothing (the hand
// being empty) is about everything.
bool mentions_any(const Fact& fact, const std::set<ObjectId>& objects) {
  if (fact.arity == 0) return true;
  for (std::uint16_t i = 0; i < fact.arity; ++i)
    if (objects.contains(fact.args[i])) return true;
  return false;
}

// The literals that turn `now` into `target`, and the facts of `target`
// about the things they name that hold already and must still hold after
// (the drawer opened to take the headset back out is closed again, as it
// was), so that the world is as `target` wherever the way back touches it.
Goal difference(const State& now, const State& target) {
  std::vector<Literal> literals;
  std::set<ObjectId> named;
  auto differs = [&](const Fact& f, bool positive) {
    literals.push_back(Literal{f, positive});
    for (std::uint16_t i = 0; i < f.arity; ++i) named.insert(f.args[i]);
  };
  for (const Fact& f : target.facts())
    if (!now.holds(f)) differs(f, true);
  for (const Fact& f : now.facts())
    if (!target.holds(f)) differs(f, false);
  if (literals.empty()) return Goal(std::move(literals));
  for (const Fact& f : target.facts())
    if (now.holds(f) && mentions_any(f, named)) literals.push_back(Literal{f, true});
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
  if ((*undone)->remembered.empty())
    say(language::forgot_last((*undone)->reply), Voice::kResponse);
  else
    say(language::remember_again((*undone)->remembered.front().category), Voice::kResponse);
  put_world_back((*undone)->world, (*undone)->history);
  return tl::unexpected(Stop{});
}

void TaskLearningAgent::Session::put_world_back(const State& before, std::size_t history_size) {
  if (simulator_.history().size() <= history_size) return;
  std::vector<Action> undoing;
  // Straight back when a short search finds the way: after an undo's own
  // putting back, the actions in between would otherwise be undone one by
  // one (the headset put back in the drawer only to be taken out again).
  const bool back = back_to(before, undoing) || back_step_by_step(before, history_size, undoing);
  if (std::string said = language::put_back(world(), undoing, back); !said.empty()) say(said, Voice::kResponse);
  if (!back) say(language::could_not_put_back(), Voice::kResponse);
}

bool TaskLearningAgent::Session::back_to(const State& target, std::vector<Action>& undoing) {
  Goal back = difference(world().state, target);
  if (back.empty()) return true;
  SearchOptions options;
  options.max_depth = kPutBackDepth;
  PlanResult plan = find_plan(*world().domain, *world().universe, world().state, back, options);
  if (plan.status != SearchStatus::kSolved) return false;
  for (const Action& action : plan.plan) {
    if (!execute(action)) return false;
    undoing.push_back(action);
  }
  return true;
}

bool TaskLearningAgent::Session::back_step_by_step(const State& before, std::size_t history_size,
                                                   std::vector<Action>& undoing) {
  const std::vector<Action>& history = simulator_.history();
  std::vector<State> states{before};
  for (std::size_t i = history_size; i < history.size(); ++i)
    states.push_back(apply(*world().domain, states.back(), history[i]));
  // Each action is undone in turn, latest first: each is a short search.
  for (std::size_t i = states.size() - 1; i-- > 0;)
    if (!back_to(states[i], undoing)) return false;
  return true;
}

}  // namespace apprentice
