// Acting toward one goal (agent/actor.h).
#include "agent/actor.h"

#include <algorithm>

#include "language/generation.h"
#include "util/text.h"

namespace apprentice {

namespace {

// An action as the LLM prompt lists steps: "Open dishwasher", "Pick up
// ceramic-plate" (the paper's example), from "Open the dishwasher.".
std::string step_text(const World& world, const Action& action) {
  std::string sentence = language::describe_action(world, action);
  if (!sentence.empty() && sentence.back() == '.') sentence.pop_back();
  std::string out;
  for (const std::string& word : split_words(sentence))
    if (word != "the") out += (out.empty() ? "" : " ") + word;
  return out;
}

bool from_instructor(const std::string& source) { return source.rfind("instructor", 0) == 0; }

}  // namespace

Flow<Acted> Actor::achieve(const World& world, teaching::InProgress& work, std::string_view subtask,
                           const ActingPolicy& policy, ActingHelp& help) {
  OwnActions own;
  int actions = 0;  // the agent's own and the LLM's, tried or done
  while (!work.goal.satisfied_by(world.state)) {
    const bool over_bound = actions >= policy.max_actions;
    if (over_bound && !policy.ask_only_teacher_past_bound) {
      work.report.note = "gave up after " + std::to_string(actions) + " actions";
      return Acted::kGaveUp;
    }
    std::optional<Action> next;
    std::string source;
    if (!over_bound) {
      auto found = own_or_llm_action(world, work, subtask, policy, help, own, source);
      if (!found) return tl::unexpected(found.error());
      next = *found;
    }
    if (!next && policy.ask_instructor) {
      std::string advice;
      auto told = help.instructor_action(work, advice);
      if (!told) return tl::unexpected(told.error());
      if (!*told) return Acted::kLeftByTeacher;
      next = *told;
      source = "instructor: " + advice;
    }
    if (!next) {
      work.report.note = "no way to reach the goal";
      return Acted::kNoWay;
    }
    if (auto done = help.carry_out(*next); !done) {
      // Advice that cannot be carried out; the plan, if any, is stale.
      own.drop_plan();
      help.could_not_do(*next);
      if (!from_instructor(source)) ++actions;
      continue;
    }
    work.actions.push_back(*next);
    work.sources.push_back(source);
    work.llm_steps.push_back(step_text(world, *next));
    ++counts_.actions_executed;
    ++actions;
  }
  return Acted::kAchieved;
}

Flow<std::optional<Action>> Actor::own_or_llm_action(const World& world, teaching::InProgress& work,
                                                     std::string_view subtask, const ActingPolicy& policy,
                                                     ActingHelp& help, OwnActions& own, std::string& source) {
  OwnActions::Next next = own.next(world, work.goal, work.object, subtask, policy.own);
  if (next.searched) {
    ++counts_.searches;
    counts_.search_nodes += next.nodes;
  }
  if (next.action) {
    if (next.source == "rule") ++counts_.rule_actions;
    source = next.source;
    return next.action;
  }
  if (!policy.ask_llm) return std::optional<Action>();
  std::string advice;
  auto advised = help.llm_action(work, advice);
  if (advised && *advised) source = "llm: " + advice;
  return advised;
}

std::vector<Rule> rules_taught(const World& world, const teaching::InProgress& work, std::string_view subtask,
                               const std::string& object_text, Generalization generalization) {
  const bool all_from_rules =
      std::all_of(work.sources.begin(), work.sources.end(), [](const std::string& s) { return s == "rule"; });
  if (work.actions.empty() || all_from_rules) return {};
  Episode episode{work.start, work.actions, {}, work.goal, work.object, std::string(subtask), object_text};
  for (std::size_t i = 0; i < work.actions.size(); ++i) {
    const std::string& source = work.sources[i];
    episode.sources.push_back(source == "search" || source == "rule"
                                  ? source + ": " + format_action(*world.domain, *world.universe, work.actions[i])
                                  : source);
  }
  return learn_policy_rules(*world.domain, *world.universe, episode, generalization);
}

}  // namespace apprentice
