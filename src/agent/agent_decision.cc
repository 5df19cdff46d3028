// Deciding where a thing goes that the agent knows no goal for
// (knowledge/decision.h): its sources propose (agent/goal_proposals.h:
// likeness, induced rules, the person's and the LLM's rules; WordNet's
// nearest learned kind, agent/transfer.h; the LLM's placement), the agent
// combines them and acts alone when confident; in doubt it asks the
// teacher one yes/no that shows its evidence, and a "no" is kept as an
// exception for that kind; when nothing is likely, it asks where.
#include <algorithm>
#include <cstdio>

#include "agent/goal_repair.h"
#include "agent/goal_proposals.h"
#include "agent/session.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "language/narration_steps.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// The fleet's yes/no: "In most households I know of (3 of 4), the ketchup
// on the table goes in the fridge, and the fridge ends closed. Here too?"
std::string fleet_question(const World& world, ObjectId object, const Goal& goal, const DestinationProposal& fleet) {
  return language::capitalize(fleet_phrase(fleet)) + ", " +
         language::goal_outcome(world, object, goal, language::spoken_name_and_location(world, object)) + ". Here too?";
}

bool is_analogy(const DestinationProposal& p) { return p.reason.starts_with("analogy: "); }

// The kinds taught that a decision's question shows ("like the banana and
// the apple"): the first two named by its support, as evidence_phrase says
// them.
std::vector<std::string> shown_kinds(std::span<const DestinationProposal> support) {
  std::vector<std::string> kinds;
  for (const DestinationProposal& p : support)
    for (const std::string& kind : p.evidence)
      if (kinds.size() < 2 && std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  return kinds;
}

// Whether two things are of one class as far as the question shows: like
// some same kind taught, or (neither like any) placed alike by the sources.
bool shown_alike(const std::vector<std::string>& one, const std::vector<std::string>& other) {
  if (one.empty() || other.empty()) return one.empty() && other.empty();
  return std::any_of(one.begin(), one.end(),
                     [&](const std::string& kind) { return std::find(other.begin(), other.end(), kind) != other.end(); });
}

// Below this belief, in the thing asked about or another, a question about
// several things was more often "no" than the beliefs said (the TidyBot
// benchmark's development half, docs/benchmarks.md).
constexpr double kAskTogetherAt = 0.75;

// How many of `beliefs` (most probable first) to ask about with a thing the
// agent believes goes there at `belief`: the most questions a "yes" saves
// on average, against the second question a "no" costs (the thing asked
// about again alone), with the beliefs as the chance that each is right.
std::size_t worth_asking_together(double belief, const std::vector<double>& beliefs) {
  std::size_t best = 0;
  if (belief < kAskTogetherAt) return 0;
  double best_gain = 0, all_right = belief;
  for (std::size_t k = 1; k <= beliefs.size(); ++k) {
    all_right *= beliefs[k - 1];
    const double gain = all_right * static_cast<double>(k) - (1 - all_right);
    if (beliefs[k - 1] < kAskTogetherAt) break;
    if (gain > best_gain) best = k, best_gain = gain;
  }
  return best;
}

std::string percent(double confidence) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", confidence);
  return text;
}

// Where the goal came from, for the object's report: the strongest support.
GoalSource goal_source_of(const Decision& decision) {
  if (decision.support.empty()) return GoalSource::kDecision;
  const DestinationProposal& top = decision.support.front();
  if (std::any_of(decision.support.begin(), decision.support.end(), is_analogy) &&
      (top.source == ProposalSource::kMemory || top.source == ProposalSource::kAnalogy))
    return GoalSource::kAnalogy;
  switch (top.source) {
    case ProposalSource::kMemory:
    case ProposalSource::kAnalogy:
    case ProposalSource::kSimilarity: return GoalSource::kLikeness;
    case ProposalSource::kInducedRule: return GoalSource::kRule;
    case ProposalSource::kPersonRule: return GoalSource::kPersonRule;
    case ProposalSource::kLlmPlacement:
    case ProposalSource::kLlmExamples:
    case ProposalSource::kLlmRule: return GoalSource::kLlm;
    case ProposalSource::kFleet: return GoalSource::kFleet;
  }
  return GoalSource::kDecision;
}

}  // namespace

TaskLearningAgent::Session::Flow<TaskLearningAgent::Session::ProposalAnswer>
TaskLearningAgent::Session::answer_to_proposal(const Question& asked, ObjectId object) {
  const World& w = world();
  auto about_it = [&](const language::Reply& r) {
    const auto* given = std::get_if<language::GoalGiven>(&r);
    if (given == nullptr) return false;
    std::vector<ObjectId> mentioned = given->goal.objects();
    return std::find(mentioned.begin(), mentioned.end(), object) != mentioned.end();
  };
  // The goal proposed: a goal said in its place is a yes when it is the
  // same, else a no with the goal as its rest (language::read_reply).
  language::ReplyContext at = context(language::Asked::kYesNo, object);
  at.proposal = asked.goal;
  auto heard = converse(
      asked, at,
      [&](const language::Reply& r) -> std::optional<std::string> {
        if (std::holds_alternative<language::YesNo>(r) || std::holds_alternative<language::Finished>(r) ||
            about_it(r))
          return std::nullopt;
        return language::asked_yes_or_no();
      },
      // Where the thing goes instead, said in place of "no".
      [&](const std::string& text) -> std::optional<language::Reply> {
        language::Reply where = agent_.understanding_.reply(w, context(language::Asked::kGoal, object), text);
        if (about_it(where)) return where;
        return std::nullopt;
      });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) return ProposalAnswer{};
  std::string text = heard->text;
  language::Reply reply = std::move(*heard->reply);
  if (const auto* ended = std::get_if<language::Finished>(&reply))
    return ProposalAnswer{false, std::nullopt, *ended, text};
  if (const auto* yes_no = std::get_if<language::YesNo>(&reply)) {
    // "no, it goes in the bottom drawer", "yes, and close it", "yes but
    // leave the door open": the rest is where it goes, read as the answer
    // to where it goes. What does not say where it goes is heard at the
    // next question after a no.
    std::optional<language::GoalGiven> where = agent_.understanding_.goal_in_rest(w, at, *yes_no);
    // "yep, but mittens go in the top drawer w the socks", asked with the
    // mittens: where another thing still to come goes, learned for when it
    // comes (and so not settled by the yes).
    bool said_for_later = false;
    if (where && !about_it(language::Reply(*where))) {
      std::optional<ObjectId> ahead;
      if (!why_not_a_goal_for(object, language::Reply(*where), ahead) && ahead) {
        begin_lesson(text);
        bool say_norm = false;
        const language::GoalGiven later = with_doors_closed(*ahead, *where, say_norm);
        const std::string source = "instructor: " + apprentice::quoted(text);
        say(language::read_back_goal_for_later(w, *ahead, later.goal) +
            (say_norm ? " " + language::closing_norm_note() : ""));
        if (auto s = learn_goal(*ahead, later.goal, source); !s) return stop(s.error());
        if (auto s = learn_goals_of_others(object, *ahead, later, text, source); !s) return stop(s.error());
        said_for_later = true;
      }
      where.reset();
    }
    // "yeah, and envelopes as well": a yes, and the same for those.
    if (where && yes_no->yes && asked.goal && where->goal == *asked.goal) {
      begin_lesson(text);
      const std::string source = "instructor: " + apprentice::quoted(text);
      if (auto s = learn_goals_of_others(object, object, *where, text, source); !s) return stop(s.error());
      return ProposalAnswer{true, std::nullopt};
    }
    if (!where) {
      if (yes_no->yes) {
        if (!said_for_later) begin_lesson(text);
        return ProposalAnswer{true, std::nullopt};
      }
      if (!yes_no->rest.empty() && !said_for_later) conversation_.answer_ahead(yes_no->rest);
      return ProposalAnswer{false, std::nullopt};
    }
    reply = std::move(*where);
  }
  bool say_norm = false;
  const language::GoalGiven given = with_doors_closed(object, std::get<language::GoalGiven>(reply), say_norm);
  begin_lesson(heard->text);
  say(language::read_back_goal(w, object, given.goal) + (say_norm ? " " + language::closing_norm_note() : ""));
  const std::string source = "instructor: " + apprentice::quoted(heard->text);
  if (auto s = learn_goal(object, given.goal, source); !s) return stop(s.error());
  if (auto s = learn_goals_of_others(object, object, given, heard->text, source); !s) return stop(s.error());
  return ProposalAnswer{false, given.goal};
}

std::vector<DestinationProposal> TaskLearningAgent::Session::proposals_for(ObjectId object) const {
  GoalSources::Asking asking;
  // What other households of the store chose for this kind.
  if (agent_.options_.fleet_prior) asking.fleet = &agent_.knowledge_.fleet;
  asking.llm = agent_.options_.condition.llm;
  return sources_.proposals_for(world(), goal_key(object), object, asking);
}

void TaskLearningAgent::Session::consult_llm(ObjectId object) {
  if (agent_.llm_ == nullptr || !agent_.options_.condition.llm || sources_.llm_consulted()) return;
  const World& w = world();
  std::vector<ObjectId> things;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (o == object || progress_.still_to_come(world(), o)) things.push_back(o);
  std::vector<GoalKnowledge> taught;
  for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
    if (g.key.task == progress_.task.name) taught.push_back(g);
  sources_.consult_llm(*agent_.llm_, w, taught, things, current().places, said_scope(),
                       agent_.understanding_.lexicon());
}

std::vector<std::pair<ObjectId, Goal>> TaskLearningAgent::Session::asked_together(ObjectId object,
                                                                                 const Decision& asked,
                                                                                 std::size_t places,
                                                                                 const DecisionPolicy& policy) const {
  const Destination& destination = *asked.destination;
  const std::vector<std::string> like = shown_kinds(asked.support);
  std::vector<std::pair<double, std::pair<ObjectId, Goal>>> candidates;
  const World& w = world();
  for (ObjectId other : w.universe->of_kind(ObjectKind::kItem)) {
    if (other == object || !progress_.still_to_come(world(), other) || sources_.settled(other)) continue;
    if (agent_.knowledge_.goals.find(goal_key(other)) != nullptr) continue;
    std::vector<DestinationProposal> proposals = proposals_for(other);
    // What was learned for its own kind elsewhere is asked about alone.
    if (std::any_of(proposals.begin(), proposals.end(),
                    [](const DestinationProposal& p) { return p.source == ProposalSource::kMemory; }))
      continue;
    Decision decision = decide(proposals, places, policy);
    if (decision.kind != Decision::Kind::kConfirm || !decision.destination || !(*decision.destination == destination) ||
        !shown_alike(like, shown_kinds(decision.support)))
      continue;
    if (auto goal = goal_at(w, destination, other))
      candidates.emplace_back(decision.confidence, std::make_pair(other, std::move(*goal)));
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<double> beliefs;
  for (const auto& c : candidates) beliefs.push_back(c.first);
  std::vector<std::pair<ObjectId, Goal>> out;
  for (std::size_t i = 0, n = worth_asking_together(asked.confidence, beliefs); i < n; ++i)
    out.push_back(std::move(candidates[i].second));
  return out;
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_settled(ObjectId object,
                                                                                              ObjectReport& report) {
  auto settled = sources_.take_settled(object);
  if (!settled) return std::optional<Goal>();
  auto [goal, said] = std::move(*settled);
  say(language::read_back_goal(world(), object, goal));
  report.goal_source = GoalSource::kInstructor;
  if (auto s = learn_goal(object, goal, "instructor: " + apprentice::quoted(said) + " (asked together)"); !s)
    return stop(s.error());
  return std::optional<Goal>(std::move(goal));
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_by_decision(
    ObjectId object, ObjectReport& report) {
  if (auto settled = goal_settled(object, report); !settled || *settled) return settled;
  if (agent_.options_.condition.llm) consult_llm(object);
  std::vector<DestinationProposal> proposals = proposals_for(object);
  if (proposals.empty()) return std::optional<Goal>();
  const World& w = world();
  const bool teacher = learning_ && agent_.options_.condition.instruction;
  const std::size_t places = place_count(w, current().places);
  DecisionPolicy policy = agent_.options_.decision;
  // The LLM placed the thing by the person's own rule: our reading of the
  // same words disagreeing is no dispute (the LLM reads them better).
  // It is also no independent expert then: our reading weighs 0.35 (on
  // the TidyBot development half, b-alone+llm: 0.5 gave 94.6% right and
  // 2.1% wrong, 0.35 95.7% and 2.5%, 0.25 96.1% and 2.8%).
  if (sources_.llm_placed_by_persons_rule()) {
    policy.not_disputing.push_back(ProposalSource::kPersonRule);
    policy.weights.try_emplace(ProposalSource::kPersonRule, 0.35);
  }
  bool together_refused = false;
  // After a "no" to this thing alone, a second guess was right about as
  // often as not (the TidyBot benchmark's development half, b-teacher: 40
  // "yes" and 20 "no" to a second yes/no), so the next question is where
  // it goes: never more questions, and fewer.
  bool refused_alone = false;
  for (bool first = true;; first = false) {
    Decision decision = decide(proposals, places, policy);
    // What was learned for this very kind in another task or subtask is
    // always worth a yes/no, however the other sources lean: before asking
    // where, and instead of a place that only other kinds suggest (the
    // ceramic plate taught for the dishwasher is not sent to the garbage
    // because the paper plate went there).
    auto memory = std::find_if(proposals.begin(), proposals.end(),
                               [](const DestinationProposal& p) { return p.source == ProposalSource::kMemory; });
    if (memory != proposals.end() &&
        (decision.kind == Decision::Kind::kAskWhere || decision.destination != memory->destination)) {
      auto belief = std::find_if(decision.beliefs.begin(), decision.beliefs.end(),
                                 [&](const Belief& b) { return b.destination == memory->destination; });
      decision.kind = Decision::Kind::kConfirm;
      decision.destination = memory->destination;
      decision.confidence = belief == decision.beliefs.end() ? memory->confidence : belief->probability;
      decision.support = belief == decision.beliefs.end() ? std::vector<DestinationProposal>{*memory} : belief->support;
    }
    if (!decision.destination) return std::optional<Goal>();
    std::optional<Goal> goal = goal_at(w, *decision.destination, object);
    if (!goal) return std::optional<Goal>();
    // A destination says the doors the examples or the rule said; a door
    // they said nothing of is closed after, as the teacher's goals are.
    goal = with_closings(w, *goal,
                         closings_to_complete(w, *goal, object, agent_.knowledge_.goals, progress_.doors_left_open));
    if (first) {
      if (const std::vector<ObjectId> places = destinations(w, *goal, object); !places.empty())
        report.proposed = w.universe->name(places.front());
      report.belief = decision.confidence;
    }
    if (decision.kind == Decision::Kind::kAskWhere || (refused_alone && decision.kind == Decision::Kind::kConfirm))
      return std::optional<Goal>();
    const std::string evidence = evidence_phrase(w, decision.support);
    const std::string as = evidence.empty() ? "" : ", " + evidence;
    if (decision.kind == Decision::Kind::kConfirm) {
      if (!teacher) {
        if (!learning_ || report.note.empty())
          report.note = language::not_sure_enough(w, object, *goal, evidence, percent(decision.confidence));
        return std::optional<Goal>();
      }
      // Things still to come that the decision would ask about with the
      // same place are asked about in the same question: a "yes" settles
      // them all.
      std::vector<std::pair<ObjectId, Goal>> together;
      if (!together_refused) together = asked_together(object, decision, places, policy);
      std::vector<std::string> others;
      for (const auto& [other, its_goal] : together) others.push_back(language::spoken_name(w, other));
      // The fleet's own question when it alone is asked about.
      std::string asked =
          decision.support.front().source == ProposalSource::kFleet && others.empty()
              ? fleet_question(w, object, *goal, decision.support.front())
              : language::ask_goal_proposed(w, object, *goal, evidence, others);
      Question q = question(QuestionKind::kConfirmGoal, asked, object, goal);
      for (const auto& entry : together) q.together.push_back(entry.first);
      proposals_asked_.push_back(ProposalAsked{object, *goal, evidence});
      for (const auto& [other, its_goal] : together) proposals_asked_.push_back(ProposalAsked{other, its_goal, evidence});
      const std::size_t rules_before = sources_.said_rules().all().size();
      auto answer = answer_to_proposal(q, object);
      if (!answer) return tl::unexpected(answer.error());
      if (answer->ended) {
        auto left = leave_as_told(object, *answer->ended, answer->text, report);
        if (!left) return tl::unexpected(left.error());
        if (*left) return std::optional<Goal>();
        continue;  // "no" to leaving the rest: asked again
      }
      if (!answer->instead && !answer->yes && !together.empty()) {
        // A "no" to several things: at least one does not go there. Ask
        // about this one alone.
        together_refused = true;
        // A rule said along with the "no" speaks now.
        if (sources_.said_rules().all().size() > rules_before) proposals = proposals_for(object);
        if (proposals.empty()) return std::optional<Goal>();
        continue;
      }
      // (A thing the yes said goes elsewhere has its own goal now.)
      if (answer->yes)
        for (auto& [other, its_goal] : together)
          if (agent_.knowledge_.goals.find(goal_key(other)) == nullptr)
            sources_.settle(other, std::move(its_goal), "yes, with " + language::spoken_name(w, object));
      if (answer->instead) {
        // "No, it goes in the garbage": the teacher's own goal, learned.
        sources_.refuse(goal_key(object).category, *decision.destination);
        report.goal_source = GoalSource::kInstructor;
        return answer->instead;
      }
      if (!answer->yes) {
        // An exception: this kind does not go there, whatever the class says.
        sources_.refuse(goal_key(object).category, *decision.destination);
        refused_alone = true;
        // A rule said with the "no" ("lol no. books and notebooks go on the
        // shelf") speaks now: proposed again, without what was refused.
        // Else the same proposals without it (no news taken mid-question).
        proposals = sources_.said_rules().all().size() > rules_before
                        ? proposals_for(object)
                        : without_destination(proposals, *decision.destination);
        if (proposals.empty()) return std::optional<Goal>();
        continue;
      }
      say(language::read_back_goal(w, object, *goal));
    } else if (learning_) {
      say(language::capitalize(language::goal_outcome(w, object, *goal, language::spoken_name_and_location(w, object))) +
          as + ".");
    }
    const DestinationProposal& top = decision.support.front();
    const bool by_analogy = is_analogy(top);
    const std::string how = decision.kind == Decision::Kind::kConfirm ? "as the teacher confirmed"
                                                                       : "confidence " + percent(decision.confidence);
    // Said to a person (run's summary): the thing as people name it, never
    // its id.
    const std::string thing = language::spoken_name_and_location(w, object);
    if (by_analogy)
      report_.analogies.push_back("took the goal of the " + language::spoken_category(top.evidence.front()) + " for " +
                                  thing + ", " + how);
    else
      report_.analogies.push_back("decided that " + language::goal_outcome(w, object, *goal, thing) + as + " (" + how +
                                  ")");
    if (learning_) {
      // A class rule is kept in English ("dirty clothes go in the laundry
      // hamper, as said: ..."): `knowledge` shows where a goal came from.
      std::string source = by_analogy ? top.reason : "decision: " + (top.rule ? say_class_rule(*top.rule) : top.reason);
      if (decision.kind == Decision::Kind::kConfirm) source += " (confirmed)";
      if (auto s = learn_goal(object, *goal, source); !s) return stop(s.error());
    }
    report.goal_source = goal_source_of(decision);
    report.because = evidence;
    return goal;
  }
}

}  // namespace apprentice
