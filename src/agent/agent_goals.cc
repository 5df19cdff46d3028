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

namespace {

// The statements of a retrieval not seen in an earlier round for the same
// object (a re-prompt may repeat them).
std::vector<llm::Candidate> unseen(std::vector<llm::Candidate> candidates, std::vector<std::string>& seen) {
  std::vector<llm::Candidate> out;
  for (llm::Candidate& candidate : candidates) {
    std::string key = to_lower(join(split_words(candidate.text), " "));
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(std::move(key));
    out.push_back(std::move(candidate));
  }
  return out;
}

}  // namespace

// The LLM's goal statements are analysed and repaired (agent/goal_repair.h),
// then Algorithm 5 (llm::finalize_choice) chooses among them: the
// instructor confirms one, or without an instructor the best usable one is
// taken. When none is accepted, the model is asked again with the rejected
// statements in the prompt (the paper's future work), then the instructor
// is asked for a description (goal_from_instructor).
Result<std::optional<Goal>> TaskLearningAgent::Session::goal_from_llm(const Current& current, ObjectId object,
                                                                      ObjectReport& report) {
  LlmAdvisor& llm = *agent_.llm_;
  const AgentOptions& options = agent_.options_;
  const GoalRepairOptions& repair = options.goal_repair;
  const bool instructed = options.condition.instruction;
  const bool repairing = format_goal_repair(repair) != "none";
  llm::TaskContext context = llm_context(current, object);
  llm::ChoiceOptions choosing;
  choosing.offer_ungrounded = options.offer_ungrounded;
  choosing.ask_description = false;  // after re-prompting, by goal_from_instructor
  choosing.sort_by_probability = !repair.choose;
  choosing.unattended =
      options.offer_ungrounded ? llm::UnattendedPolicy::kFirst : llm::UnattendedPolicy::kFirstGrounded;
  std::vector<std::string> seen;
  const int rounds = 1 + (repair.reprompt ? std::max(options.max_reprompts, 0) : 0);
  for (int round = 0; round < rounds; ++round) {
    std::vector<llm::Candidate> candidates = unseen(llm.goals(context), seen);
    if (llm.last_failure() && candidates.empty()) {
      dialogue_->say("I could not reach the language model (" + llm.last_failure()->message + ")" +
                     (instructed ? ", so I will ask." : "."));
      return std::optional<Goal>();
    }
    if (candidates.empty()) break;  // nothing new: a corpus or cassette has no answer to a re-prompt
    GoalAnalysis analysis =
        analyse_goals(agent_.understanding_, world(), object, candidates, agent_.knowledge_.goals, repair);
    report_.search_nodes += analysis.search_nodes;
    for (const AnalysedGoal& analysed : analysis.goals) {
      if (!analysed.goal)
        spdlog::info("LLM goal {} for {} is unusable: {}", apprentice::quoted(analysed.candidate.text),
                     describe_object(object), analysed.failure);
      else if (analysed.repaired())
        spdlog::info("LLM goal {} for {} repaired: {}", apprentice::quoted(analysed.candidate.text),
                     describe_object(object), describe_repairs(world(), analysed));
    }
    // Without an instructor the best usable goal is taken. With one, every
    // usable goal is offered (Algorithm 5), or with `choose` only the best,
    // if the retrieved statements agree on it (GoalRepairOptions::offer_share).
    const AnalysedGoal* best = analysis.goals.empty() ? nullptr : &analysis.goals.front();
    const bool best_agreed = best && best->goal && best->share >= repair.offer_share - 1e-9;
    auto usable = [&](const llm::Candidate& c) {
      const AnalysedGoal* analysed = analysis.find(c);
      if (analysed == nullptr || !analysed->goal) return false;
      return !instructed || !repair.choose || (best_agreed && analysed == best);
    };
    // The instructor hears the goal the agent would adopt, in English; the
    // model's own words when nothing is repaired or it does not ground.
    llm::CallbackConfirmer confirmer([&](llm::QueryKind, const llm::Candidate& c) -> Result<bool> {
      const AnalysedGoal* analysed = analysis.find(c);
      const std::optional<Goal> goal = analysed ? analysed->goal : std::nullopt;
      std::string question = goal && repairing ? language::say_goal_question(world(), object, *goal, true)
                                               : language::say_goal_question(world(), object, c.text);
      auto reply = ask(QuestionKind::kConfirmGoal, question, object, goal);
      if (!reply) return tl::unexpected(reply.error());
      return read_yes_no(*reply).value_or(false);
    });
    auto choice = llm::finalize_choice(analysis.ordered_candidates(), llm::QueryKind::kGoal, usable,
                                       instructed ? &confirmer : nullptr, choosing);
    if (!choice) return tl::unexpected(choice.error());
    if (choice->candidate) {
      const AnalysedGoal* chosen = analysis.find(*choice->candidate);
      if (chosen == nullptr || !chosen->goal) {
        // Without an instructor the most probable statement is taken as it
        // is (the paper's Search+LLM condition); one that cannot be used
        // fails the object.
        report.note = "LLM goal " + apprentice::quoted(choice->text) + " is unusable: " +
                      (chosen ? chosen->failure_kind : std::string("ungrounded"));
        return std::optional<Goal>();
      }
      std::string repairs = describe_repairs(world(), *chosen);
      std::string source = std::string(choice->candidate->source == llm::ResponseSource::kCorpus ? "corpus" : "llm") +
                           ": " + apprentice::quoted(choice->text) + (repairs.empty() ? "" : " (" + repairs + ")") +
                           (instructed ? " (confirmed)" : "");
      if (auto s = learn_goal(current, object, *chosen->goal, source); !s) return tl::unexpected(s.error());
      report.goal_source = "llm";
      return chosen->goal;
    }
    // Nothing accepted: the failure context of the next query.
    for (const llm::Candidate& candidate : candidates) context.rejected.push_back(candidate.text);
  }
  if (!instructed && report.note.empty()) report.note = "no usable LLM goal";
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
