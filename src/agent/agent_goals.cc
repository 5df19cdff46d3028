// Acquiring goals: from the LLM (confirmed by the instructor where there is
// one) or from the instructor, and learning them as goal knowledge.
#include <algorithm>

#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// "done", "leave it", "skip it": the object stays where it is (the reader
// takes the script's "You are done." at a goal question; these are what
// people say instead).
bool leaves_it_alone(const std::string& text) {
  std::string said = to_lower(trim(text));
  while (!said.empty() && (said.back() == '.' || said.back() == '!')) said.pop_back();
  for (std::string_view polite : {"please ", "just ", "ok ", "okay "})
    if (said.starts_with(polite)) said = said.substr(polite.size());
  static const char* const kAlone[] = {"done", "skip", "skip it", "skip that", "skip this one", "leave it",
                                       "leave it there", "leave it alone", "leave that", "leave that one",
                                       "it stays", "it stays there", "it stays where it is", "nowhere", "nothing",
                                       "pass", "ignore it", "don't move it", "do not move it", "keep it there",
                                       "it can stay", "it can stay there", "leave it be"};
  return std::any_of(std::begin(kAlone), std::end(kAlone), [&](const char* a) { return said == a; });
}

}  // namespace

GoalKey TaskLearningAgent::Session::goal_key(ObjectId object) const {
  return GoalKey{progress_.task.name, current().verb, world().universe->info(object).category,
                 world().universe->info(current().places.front()).category};
}

llm::TaskContext TaskLearningAgent::Session::llm_context(ObjectId object) const {
  const ObjectInfo& place = world().universe->info(current().places.front());
  std::string relation = place.kind == ObjectKind::kSurface ? "on " : "in ";
  std::string place_words = place.category;
  std::replace(place_words.begin(), place_words.end(), '-', ' ');
  return llm::TaskContext{progress_.task.name, current().verb, world().location,
                          world().universe->info(object).category, relation + place_words};
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::acquire_goal(ObjectId object,
                                                                                             ObjectReport& report) {
  std::optional<Goal> goal;
  if (agent_.options_.condition.llm) {
    auto from_llm = goal_from_llm(object, report);
    if (!from_llm) return from_llm;
    goal = *from_llm;
  }
  if (!goal && agent_.options_.condition.instruction) {
    auto from_instructor = goal_from_instructor(object, report);
    if (!from_instructor) return from_instructor;
    goal = *from_instructor;
  }
  if (!goal && report.note.empty()) report.note = "no goal";
  return goal;
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_from_llm(ObjectId object,
                                                                                              ObjectReport& report) {
  LlmAdvisor& llm = *agent_.llm_;
  std::vector<llm::Candidate> candidates = llm.goals(llm_context(object));
  const bool instructed = agent_.options_.condition.instruction;
  if (llm.last_failure() && candidates.empty())
    say("I could not reach the language model (" + llm.last_failure()->message + ")" +
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
      std::string text = language::say_goal_question(world(), object, candidate.text);
      auto yes = confirm(question(QuestionKind::kConfirmGoal, text, object, meaning.goal));
      if (!yes) return tl::unexpected(yes.error());
      if (!*yes) continue;
      say(language::read_back_goal(world(), object, *meaning.goal));
    }
    std::string source = std::string(candidate.source == llm::ResponseSource::kCorpus ? "corpus" : "llm") + ": " +
                         apprentice::quoted(candidate.text) + (instructed ? " (confirmed)" : "");
    if (auto s = learn_goal(object, *meaning.goal, source); !s) return stop(s.error());
    report.goal_source = "llm";
    return meaning.goal;
  }
  return std::optional<Goal>();
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_from_instructor(
    ObjectId object, ObjectReport& report) {
  const World& w = world();
  Question asked = question(QuestionKind::kSubtaskStep, language::ask_goal(w, object), object);
  auto heard = converse(asked, context(language::Asked::kGoal, object),
                        [&](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::Finished>(r)) return std::nullopt;
                          const auto* given = std::get_if<language::GoalGiven>(&r);
                          if (given == nullptr)
                            return "I asked where " + language::spoken_name(w, object) + " goes.";
                          std::vector<ObjectId> mentioned = given->goal.objects();
                          if (std::find(mentioned.begin(), mentioned.end(), object) != mentioned.end())
                            return std::nullopt;
                          // A goal about something else is never stored as this one's.
                          std::vector<std::string> names;
                          for (ObjectId o : mentioned)
                            if (w.universe->info(o).kind == ObjectKind::kItem) names.push_back(language::spoken_name(w, o));
                          return "That says what becomes of " + (names.empty() ? "other things" : language::list_phrase(names)) +
                                 ", but I asked about " + language::spoken_name_and_location(w, object) + ".";
                        },
                        [&](const std::string& text) {
                          if (leaves_it_alone(text)) return std::optional<language::Reply>(language::Finished{});
                          return goal_like_another(object, text);
                        });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) {
    report.note = "no usable goal from the instructor";
    return std::optional<Goal>();
  }
  begin_lesson(heard->text);
  if (std::holds_alternative<language::Finished>(*heard->reply)) {
    report.note = "left where it is, as the instructor said";
    say("I will leave " + language::spoken_name_and_location(w, object) + " as it is.");
    return std::optional<Goal>();
  }
  const Goal& goal = std::get<language::GoalGiven>(*heard->reply).goal;
  say(language::read_back_goal(w, object, goal));
  if (auto s = learn_goal(object, goal, "instructor: " + apprentice::quoted(heard->text)); !s) return stop(s.error());
  report.goal_source = "instructor";
  return std::optional<Goal>(goal);
}

std::optional<language::Reply> TaskLearningAgent::Session::goal_like_another(ObjectId object,
                                                                             const std::string& text) const {
  std::string said = to_lower(trim(text));
  while (!said.empty() && (said.back() == '.' || said.back() == '!')) said.pop_back();
  // "same as the soda can", "the same place as the mug", "like the soda
  // cans", "where the soda can goes".
  std::string other;
  for (std::string_view marker : {"same place as ", "same way as ", "same as ", "just like ", "like ", "where "}) {
    std::size_t at = said.find(marker);
    if (at == std::string::npos) continue;
    other = said.substr(at + marker.size());
    break;
  }
  for (std::string_view tail : {" goes", " go", " went", " did", " does"})
    if (other.size() > tail.size() && other.ends_with(tail)) other.resize(other.size() - tail.size());
  for (std::string_view lead : {"those ", "that ", "this ", "the ", "a ", "an "})
    if (other.starts_with(lead)) other = other.substr(lead.size());
  if (other.empty()) return std::nullopt;
  std::vector<std::string> kinds;
  if (auto here = agent_.understanding_.category(world(), other)) kinds = {*here};
  else kinds = known_kinds(other);
  if (kinds.size() != 1) return std::nullopt;
  // The goal learned for that kind in this subtask, else in any.
  GoalKey key = goal_key(object);
  key.category = kinds.front();
  const GoalKnowledge* known = agent_.knowledge_.goals.find(key);
  for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
    if (known == nullptr && g.key.category == kinds.front()) known = &g;
  if (known == nullptr)
    return language::Reply(language::Unusable{
        "I have not learned where " + language::kind_goes(kinds.front()) + " yet. Where should " +
            language::spoken_name(world(), object) + " go?",
        agent_.understanding_.example_replies(world(), context(language::Asked::kGoal, object)), std::nullopt});
  std::optional<Goal> goal = instantiate_goal(world(), *known, object);
  if (!goal) return std::nullopt;
  return language::Reply(language::GoalGiven{*goal});
}

Status TaskLearningAgent::Session::learn_goal(ObjectId object, const Goal& goal, const std::string& source) {
  // What "the door" and "close it" mean next: the place this goal names.
  for (const Literal& l : goal.literals)
    if ((l.fact.predicate == world().vocabulary.in || l.fact.predicate == world().vocabulary.on) && l.fact.arity == 2 &&
        l.fact.args[0] == object)
      recent_place_ = l.fact.args[1];
  auto knowledge = generalize_goal(world(), goal_key(object), object, goal, Provenance{describe_object(object), source});
  if (!knowledge) {
    // Still usable for this object, just not learnable for its category.
    spdlog::warn("goal not learned: {}", knowledge.error().message);
    return {};
  }
  std::optional<GoalKnowledge> previous;
  if (const GoalKnowledge* known = agent_.knowledge_.goals.find(knowledge->key)) previous = *known;
  agent_.knowledge_.goals.add(*knowledge);
  ++progress_.goals_learned;
  return store_goal(*knowledge, std::move(previous));
}

}  // namespace apprentice
