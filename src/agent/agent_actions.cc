// Achieving a goal: the inner loop of Algorithm 1, with learned rules
// consulted before search and before asking, and rule learning once the
// goal holds.
#include <deque>
#include <map>

#include "agent/session.h"
#include "language/generation.h"
#include "search/iterative_deepening.h"
#include "util/log.h"
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

}  // namespace

Result<bool> TaskLearningAgent::Session::achieve(const Current& current, ObjectId object, const Goal& goal,
                                                 ObjectReport& report) {
  const Condition& condition = agent_.options_.condition;
  episode_start_ = world().state;
  episode_actions_.clear();
  episode_sources_.clear();
  llm_steps_.clear();
  std::deque<Action> plan;
  // A failed search is not repeated until some other source has changed
  // the state.
  std::optional<State> searched_in;
  int actions = 0;
  while (!goal.satisfied_by(world().state)) {
    if (actions >= agent_.options_.max_actions_per_object) {
      report.note = "gave up after " + std::to_string(actions) + " actions";
      return false;
    }
    std::optional<Action> next;
    std::string source;
    if (!plan.empty()) {
      next = plan.front();
      plan.pop_front();
      source = "search";
    }
    if (!next && agent_.options_.use_rules) {
      MatchQuery query{&world().state, &goal, object, current.verb};
      if (auto proposal = agent_.knowledge_.rules.select(*world().domain, *world().universe, query)) {
        next = proposal->action;
        source = "rule";
        ++report_.rule_actions;
      }
    }
    if (!next && learning_ && condition.search_depth > 0 && searched_in != world().state) {
      SearchOptions options;
      options.max_depth = condition.search_depth;
      PlanResult result = find_plan(*world().domain, *world().universe, world().state, goal, options);
      ++report_.searches;
      report_.search_nodes += result.statistics.nodes_expanded;
      searched_in = world().state;
      if (result.status == SearchStatus::kSolved && !result.plan.empty()) {
        plan.assign(result.plan.begin() + 1, result.plan.end());
        next = result.plan.front();
        source = "search";
      }
    }
    if (!next && learning_ && condition.llm) {
      auto from_llm = action_from_llm(current, object, goal);
      if (!from_llm) return tl::unexpected(from_llm.error());
      if (*from_llm) {
        next = *from_llm;
        source = "llm: " + advice_;
      }
    }
    if (!next && learning_ && condition.instruction) {
      auto from_instructor = action_from_instructor(current, object, goal);
      if (!from_instructor) return tl::unexpected(from_instructor.error());
      if (*from_instructor) {
        next = *from_instructor;
        source = "instructor: " + advice_;
      }
    }
    if (!next) {
      report.note = "no way to reach the goal";
      if (!learning_)
        report_.help_needed.push_back("an action for " + describe_object(object) + " towards " +
                                      format_goal(*world().domain, *world().universe, goal));
      return false;
    }
    if (auto status = simulator_.execute(*next); !status) {
      // Advice that cannot be carried out; the plan, if any, is stale.
      plan.clear();
      if (dialogue_) dialogue_->say("I cannot do that: " + status.error().message + ".");
      ++actions;
      continue;
    }
    episode_actions_.push_back(*next);
    episode_sources_.push_back(source);
    llm_steps_.push_back(step_text(world(), *next));
    ++report_.actions_executed;
    ++actions;
  }
  if (learning_) {
    if (auto s = learn_rules(current, object, goal); !s) return tl::unexpected(s.error());
  }
  return true;
}

// The LLM's next steps, chosen by Algorithm 5 (llm::finalize_choice): the
// most probable step that grounds and can be done now, confirmed by the
// instructor where there is one.
Result<std::optional<Action>> TaskLearningAgent::Session::action_from_llm(const Current& current, ObjectId object,
                                                                          const Goal& goal) {
  LlmAdvisor& llm = *agent_.llm_;
  std::string goal_text = language::describe_goal_instruction(world(), object, goal);
  if (!goal_text.empty() && goal_text.back() == '.') goal_text.pop_back();
  auto known = [this](std::string_view word) { return agent_.understanding_.is_known_action_word(word); };
  std::vector<llm::Candidate> candidates = llm.actions(llm_context(current, object), goal_text, llm_steps_, known);
  const bool instructed = agent_.options_.condition.instruction;
  if (llm.last_failure() && candidates.empty())
    dialogue_->say("I could not reach the language model (" + llm.last_failure()->message + ")" +
                   (instructed ? ", so I will ask." : "."));
  std::map<std::string, Action> usable;  // by the candidate's text
  for (const llm::Candidate& candidate : candidates) {
    ActionMeaning meaning = agent_.understanding_.action(world(), candidate.text, object);
    if (meaning.action && is_applicable(*world().domain, world().state, *meaning.action)) {
      usable.emplace(candidate.text, *meaning.action);
      continue;
    }
    spdlog::info("LLM action {} is not usable here: {}", apprentice::quoted(candidate.text),
                 meaning.action ? "not applicable" : meaning.failure);
  }
  llm::CallbackConfirmer confirmer([&](llm::QueryKind, const llm::Candidate& c) -> Result<bool> {
    auto action = usable.find(c.text);
    std::optional<Action> proposed;
    if (action != usable.end()) proposed = action->second;
    auto reply = ask(QuestionKind::kConfirmAction, language::say_action_question(world(), object, c.text), object, goal,
                     proposed);
    if (!reply) return tl::unexpected(reply.error());
    return read_yes_no(*reply).value_or(false);
  });
  llm::ChoiceOptions choosing;
  choosing.offer_ungrounded = agent_.options_.offer_ungrounded;
  choosing.ask_description = false;  // action_from_instructor asks next
  choosing.unattended =
      agent_.options_.offer_ungrounded ? llm::UnattendedPolicy::kFirst : llm::UnattendedPolicy::kFirstGrounded;
  auto choice = llm::finalize_choice(candidates, llm::QueryKind::kAction,
                                     [&](const llm::Candidate& c) { return usable.contains(c.text); },
                                     instructed ? &confirmer : nullptr, choosing);
  if (!choice) return tl::unexpected(choice.error());
  if (!choice->candidate) return std::optional<Action>();
  auto action = usable.find(choice->candidate->text);
  if (action == usable.end()) return std::optional<Action>();  // unattended, the paper's way: unusable
  advice_ = apprentice::quoted(choice->candidate->text) + (instructed ? " (confirmed)" : "");
  return action->second;
}

Result<std::optional<Action>> TaskLearningAgent::Session::action_from_instructor(const Current& current,
                                                                                 ObjectId object, const Goal& goal) {
  for (int attempt = 0; attempt <= agent_.options_.max_retries; ++attempt) {
    auto reply = ask(QuestionKind::kNextAction, language::say_next_action_request(current.verb), object, goal);
    if (!reply) return tl::unexpected(reply.error());
    ActionMeaning meaning = agent_.understanding_.action(world(), *reply, object);
    if (meaning.action) {
      advice_ = apprentice::quoted(*reply);
      return meaning.action;
    }
    dialogue_->say(meaning.failure);
  }
  return std::optional<Action>();
}

Status TaskLearningAgent::Session::learn_rules(const Current& current, ObjectId object, const Goal& goal) {
  bool all_from_rules = std::all_of(episode_sources_.begin(), episode_sources_.end(),
                                    [](const std::string& s) { return s == "rule"; });
  if (episode_actions_.empty() || all_from_rules) return {};
  Episode episode{episode_start_, episode_actions_, {}, goal, object, current.verb, describe_object(object)};
  for (std::size_t i = 0; i < episode_actions_.size(); ++i) {
    const std::string& source = episode_sources_[i];
    episode.sources.push_back(source == "search" || source == "rule"
                                  ? source + ": " + format_action(*world().domain, *world().universe, episode_actions_[i])
                                  : source);
  }
  std::vector<Rule> rules =
      learn_policy_rules(*world().domain, *world().universe, episode, agent_.options_.generalization);
  for (Rule& rule : rules) {
    Rule copy = rule;
    if (!agent_.knowledge_.rules.add(*world().domain, std::move(rule))) continue;
    ++report_.rules_learned;
    if (agent_.store_) {
      if (auto s = agent_.store_->save_rule(*world().domain, copy); !s) return s;
    }
  }
  return {};
}

}  // namespace apprentice
