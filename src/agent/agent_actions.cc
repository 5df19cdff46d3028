// Achieving a goal: the inner loop of Algorithm 1, with learned rules
// consulted before search and before asking, and rule learning once the
// goal holds.
#include <deque>
#include <map>

#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
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

TaskLearningAgent::Session::Flow<bool> TaskLearningAgent::Session::achieve(InProgress& work) {
  const Condition& condition = agent_.options_.condition;
  ObjectReport& report = work.report;
  OwnActions own;
  int actions = 0;
  while (!work.goal.satisfied_by(world().state)) {
    // Past the bound, a program's run gives up on the object; a person is
    // asked instead, and only what the person says is done.
    const bool over_bound = actions >= agent_.options_.max_actions_per_object;
    if (over_bound && !(learning_ && person() && condition.instruction)) {
      report.note = "gave up after " + std::to_string(actions) + " actions";
      return false;
    }
    std::optional<Action> next;
    std::string source;
    if (!over_bound) {
      auto found = own_next_action(work, own, source);
      if (!found) return tl::unexpected(found.error());
      next = *found;
    }
    if (!next && learning_ && condition.instruction) {
      auto from_instructor = action_from_instructor(work);
      if (!from_instructor) return tl::unexpected(from_instructor.error());
      if (!*from_instructor) return false;  // the instructor said to leave it, or could not say
      next = *from_instructor;
      source = "instructor: " + advice_;
    }
    if (!next) {
      report.note = "no way to reach the goal";
      if (!learning_)
        report_.help_needed.push_back(language::help_needed_for_goal_to_hold(world(), work.goal));
      return false;
    }
    if (auto status = execute(*next); !status) {
      // Advice that cannot be carried out; the plan, if any, is stale.
      own.drop_plan();
      say(language::refusal(world(), *next), Voice::kResponse);
      if (source.rfind("instructor", 0) != 0) ++actions;
      continue;
    }
    work.actions.push_back(*next);
    work.sources.push_back(source);
    work.llm_steps.push_back(step_text(world(), *next));
    ++report_.actions_executed;
    ++actions;
  }
  return true;
}

TaskLearningAgent::Session::Flow<std::optional<Action>> TaskLearningAgent::Session::own_next_action(
    InProgress& work, OwnActions& own, std::string& source) {
  const Condition& condition = agent_.options_.condition;
  OwnActions::Ways ways;
  if (agent_.options_.use_rules) ways.rules = &agent_.knowledge_.rules;
  // Performing alone, the agent does what its rules say and does not search.
  if (learning_) {
    ways.search_depth = condition.search_depth;
    ways.unbounded_search = condition.unbounded_search;
  }
  OwnActions::Next next = own.next(world(), work.goal, work.object, current().verb, ways);
  if (next.searched) {
    ++report_.searches;
    report_.search_nodes += next.nodes;
  }
  if (next.action) {
    if (next.source == "rule") ++report_.rule_actions;
    source = next.source;
    return next.action;
  }
  if (learning_ && condition.llm) {
    auto from_llm = action_from_llm(work);
    if (!from_llm) return from_llm;
    if (*from_llm) source = "llm: " + advice_;
    return from_llm;
  }
  return std::optional<Action>();
}

// The LLM's next steps, chosen by Algorithm 5 (llm::finalize_choice): the
// most probable step that grounds and can be done now, confirmed by the
// instructor where there is one.
TaskLearningAgent::Session::Flow<std::optional<Action>> TaskLearningAgent::Session::action_from_llm(InProgress& work) {
  LlmAdvisor& llm = *agent_.llm_;
  std::string goal_text = language::describe_goal_instruction(world(), work.object, work.goal);
  if (!goal_text.empty() && goal_text.back() == '.') goal_text.pop_back();
  auto known = [this](std::string_view word) { return agent_.understanding_.is_known_action_word(word); };
  std::vector<llm::Candidate> candidates = llm.actions(llm_context(work.object), goal_text, work.llm_steps, known);
  const bool instructed = agent_.options_.condition.instruction;
  if (llm.last_failure() && candidates.empty())
    say(language::could_not_reach_llm(llm.last_failure()->message, instructed));
  std::map<std::string, Action> usable;  // by the candidate's text
  for (const llm::Candidate& candidate : candidates) {
    ActionMeaning meaning = agent_.understanding_.action(world(), candidate.text, work.object);
    if (meaning.action && is_applicable(*world().domain, world().state, *meaning.action)) {
      usable.emplace(candidate.text, *meaning.action);
      continue;
    }
    spdlog::info("LLM action {} is not usable here: {}", apprentice::quoted(candidate.text),
                 meaning.action ? "not applicable" : meaning.failure);
  }
  // An undo or the teacher leaving stops the choice (`stopped`).
  std::optional<Stop> stopped;
  llm::CallbackConfirmer confirmer([&](llm::QueryKind, const llm::Candidate& c) -> Result<bool> {
    auto action = usable.find(c.text);
    std::optional<Action> proposed;
    if (action != usable.end()) proposed = action->second;
    std::string text = language::say_action_question(world(), work.object, c.text);
    auto yes = confirm(question(QuestionKind::kConfirmAction, text, work.object, work.goal, proposed));
    if (yes) return *yes;
    stopped = yes.error();
    return make_error(ErrorCode::kCancelled, "the choice of an LLM action was stopped");
  });
  llm::ChoiceOptions choosing;
  choosing.offer_ungrounded = agent_.options_.offer_ungrounded;
  choosing.ask_description = false;  // action_from_instructor asks next
  choosing.unattended =
      agent_.options_.offer_ungrounded ? llm::UnattendedPolicy::kFirst : llm::UnattendedPolicy::kFirstGrounded;
  auto choice = llm::finalize_choice(candidates, llm::QueryKind::kAction,
                                     [&](const llm::Candidate& c) { return usable.contains(c.text); },
                                     instructed ? &confirmer : nullptr, choosing);
  if (stopped) return tl::unexpected(*stopped);
  if (!choice) return stop(choice.error());
  if (!choice->candidate) return std::optional<Action>();
  auto action = usable.find(choice->candidate->text);
  if (action == usable.end()) return std::optional<Action>();  // unattended, the paper's way: unusable
  advice_ = apprentice::quoted(choice->candidate->text) + (instructed ? " (confirmed)" : "");
  return std::optional<Action>(action->second);
}

TaskLearningAgent::Session::Flow<std::optional<Action>> TaskLearningAgent::Session::action_from_instructor(
    InProgress& work) {
  Question asked = question(QuestionKind::kNextAction, language::ask_next_action(world(), work.goal), work.object,
                            work.goal);
  auto heard = converse(asked, context(language::Asked::kAction, work.object),
                        [](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::ActionGiven>(r) ||
                              std::holds_alternative<language::Finished>(r))
                            return std::nullopt;
                          return language::asked_what_to_do_next();
                        });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) {
    work.report.note = "no usable action from the instructor";
    return std::optional<Action>();
  }
  begin_lesson(heard->text);
  if (std::holds_alternative<language::Finished>(*heard->reply)) {
    work.report.note = "left as it is, as the instructor said";
    say(language::will_leave_as_it_is(world(), work.object, false));
    return std::optional<Action>();
  }
  const Action& action = std::get<language::ActionGiven>(*heard->reply).action;
  for (ObjectId o : action.arguments())
    if (world().universe->info(o).kind != ObjectKind::kItem) conversation_.named_place(o);
  advice_ = apprentice::quoted(heard->text);
  return std::optional<Action>(action);
}

Status TaskLearningAgent::Session::learn_rules(const InProgress& work) {
  bool all_from_rules =
      std::all_of(work.sources.begin(), work.sources.end(), [](const std::string& s) { return s == "rule"; });
  if (work.actions.empty() || all_from_rules) return {};
  Episode episode{work.start, work.actions, {}, work.goal, work.object, current().verb, describe_object(work.object)};
  for (std::size_t i = 0; i < work.actions.size(); ++i) {
    const std::string& source = work.sources[i];
    episode.sources.push_back(source == "search" || source == "rule"
                                  ? source + ": " + format_action(*world().domain, *world().universe, work.actions[i])
                                  : source);
  }
  std::vector<Rule> rules =
      learn_policy_rules(*world().domain, *world().universe, episode, agent_.options_.generalization);
  for (Rule& rule : rules) {
    auto learned = lessons_.learn_rule(agent_.knowledge_, std::move(rule));
    if (!learned) return tl::unexpected(learned.error());
    if (*learned) ++progress_.rules_learned;
  }
  return {};
}

}  // namespace apprentice
