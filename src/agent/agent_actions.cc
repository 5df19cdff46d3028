// What the session does for its actor (agent/actor.h): asks the LLM and
// the teacher for the next action, and carries actions out.
#include <deque>
#include <map>

#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

// The LLM's next steps, chosen by Algorithm 5 (llm::finalize_choice): the
// most probable step that grounds and can be done now, confirmed by the
// instructor where there is one.
TaskLearningAgent::Session::Flow<std::optional<Action>> TaskLearningAgent::Session::llm_action(InProgress& work,
                                                                                         std::string& advice) {
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
  advice = apprentice::quoted(choice->candidate->text) + (instructed ? " (confirmed)" : "");
  return std::optional<Action>(action->second);
}

TaskLearningAgent::Session::Flow<std::optional<Action>> TaskLearningAgent::Session::instructor_action(
    InProgress& work, std::string& advice) {
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
  advice = apprentice::quoted(heard->text);
  return std::optional<Action>(action);
}

Status TaskLearningAgent::Session::carry_out(const Action& action) { return execute(action); }

void TaskLearningAgent::Session::could_not_do(const Action& action) {
  say(language::refusal(world(), action), Voice::kResponse);
}

ActingPolicy TaskLearningAgent::Session::acting_policy() const {
  const Condition& condition = agent_.options_.condition;
  ActingPolicy policy;
  if (agent_.options_.use_rules) policy.own.rules = &agent_.knowledge_.rules;
  // Performing alone, the agent does what its rules say and does not search.
  if (learning_) {
    policy.own.search_depth = condition.search_depth;
    policy.own.unbounded_search = condition.unbounded_search;
  }
  policy.ask_llm = learning_ && condition.llm;
  policy.ask_instructor = learning_ && condition.instruction;
  policy.max_actions = agent_.options_.max_actions_per_object;
  // Past the bound, a program's run gives up on the object; a person is
  // asked instead, and only what the person says is done.
  policy.ask_only_teacher_past_bound = learning_ && person() && condition.instruction;
  return policy;
}

}  // namespace apprentice
