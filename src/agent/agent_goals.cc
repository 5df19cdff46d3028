// Acquiring goals: from the LLM (confirmed by the instructor where there is
// one) or from the instructor, and learning them as goal knowledge.
#include <algorithm>

#include "agent/session.h"
#include "language/generation.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

GoalKey TaskLearningAgent::Session::goal_key(const Current& current, ObjectId object) const {
  return GoalKey{task_.name, current.verb, world().universe->info(object).category,
                 world().universe->info(current.place).category};
}

llm::TaskContext TaskLearningAgent::Session::llm_context(const Current& current, ObjectId object) const {
  const ObjectInfo& place = world().universe->info(current.place);
  std::string relation = place.kind == ObjectKind::kSurface ? "on " : "in ";
  std::string place_words = place.category;
  std::replace(place_words.begin(), place_words.end(), '-', ' ');
  return llm::TaskContext{task_.name, current.verb, world().location, world().universe->info(object).category,
                          relation + place_words};
}

Result<std::optional<Goal>> TaskLearningAgent::Session::acquire_goal(const Current& current, ObjectId object,
                                                                     ObjectReport& report) {
  std::optional<Goal> goal;
  if (agent_.options_.condition.llm) {
    auto from_llm = goal_from_llm(current, object, report);
    if (!from_llm) return from_llm;
    goal = *from_llm;
  }
  if (!goal && agent_.options_.condition.instruction) {
    auto from_instructor = goal_from_instructor(current, object, report);
    if (!from_instructor) return from_instructor;
    goal = *from_instructor;
  }
  if (!goal && report.note.empty()) report.note = "no goal";
  return goal;
}

Result<std::optional<Goal>> TaskLearningAgent::Session::goal_from_llm(const Current& current, ObjectId object,
                                                                      ObjectReport& report) {
  LlmAdvisor& llm = *agent_.llm_;
  std::vector<llm::Candidate> candidates = llm.goals(llm_context(current, object));
  const bool instructed = agent_.options_.condition.instruction;
  if (llm.last_failure() && candidates.empty())
    dialogue_->say("I could not reach the language model (" + llm.last_failure()->message + ")" +
                   (instructed ? ", so I will ask." : "."));
  for (const llm::Candidate& candidate : candidates) {
    GoalMeaning meaning = agent_.understanding_.goal(world(), candidate.text, object);
    if (!meaning.goal) {
      spdlog::info("LLM goal {} for {} does not ground: {}", apprentice::quoted(candidate.text), describe_object(object),
                   meaning.failure);
      if (!instructed) {
        // Without an instructor the most probable response is taken as it
        // is (the paper's Search+LLM condition); one that cannot be used
        // fails the object.
        report.note = "LLM goal " + apprentice::quoted(candidate.text) + " is unusable: " + meaning.failure_kind;
        return std::optional<Goal>();
      }
      continue;
    }
    if (instructed) {
      std::string question = language::say_goal_question(world(), object, candidate.text);
      auto reply = ask(QuestionKind::kConfirmGoal, question, object, meaning.goal);
      if (!reply) return tl::unexpected(reply.error());
      if (!read_yes_no(*reply).value_or(false)) continue;
    }
    std::string source = std::string(candidate.source == llm::ResponseSource::kCorpus ? "corpus" : "llm") + ": " +
                         apprentice::quoted(candidate.text) + (instructed ? " (confirmed)" : "");
    if (auto s = learn_goal(current, object, *meaning.goal, source); !s) return tl::unexpected(s.error());
    report.goal_source = "llm";
    return meaning.goal;
  }
  return std::optional<Goal>();
}

Result<std::optional<Goal>> TaskLearningAgent::Session::goal_from_instructor(const Current& current, ObjectId object,
                                                                             ObjectReport& report) {
  for (int attempt = 0; attempt <= agent_.options_.max_retries; ++attempt) {
    auto reply = ask(QuestionKind::kSubtaskStep, language::say_next_goal_request(current.verb), object);
    if (!reply) return tl::unexpected(reply.error());
    GoalMeaning meaning = agent_.understanding_.goal(world(), *reply, object);
    if (meaning.goal) {
      if (auto s = learn_goal(current, object, *meaning.goal, "instructor: " + apprentice::quoted(*reply)); !s)
        return tl::unexpected(s.error());
      report.goal_source = "instructor";
      return meaning.goal;
    }
    dialogue_->say(meaning.failure);
  }
  report.note = "no usable goal from the instructor";
  return std::optional<Goal>();
}

Status TaskLearningAgent::Session::learn_goal(const Current& current, ObjectId object, const Goal& goal,
                                              const std::string& source) {
  auto knowledge = generalize_goal(world(), goal_key(current, object), object, goal,
                                   Provenance{describe_object(object), source});
  if (!knowledge) {
    // Still usable for this object, just not learnable for its category.
    spdlog::warn("goal not learned: {}", knowledge.error().message);
    return {};
  }
  agent_.knowledge_.goals.add(*knowledge);
  ++report_.goals_learned;
  if (agent_.store_) return agent_.store_->save_goal(*knowledge);
  return {};
}

}  // namespace apprentice
