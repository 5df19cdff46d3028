// The LLM's placements in the session (agent/llm_preferences.h): asked once,
// acted on alone, confirmed by the instructor where there is one.
#include <algorithm>

#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// The placement of `thing` at `place`: in a receptacle, on a surface.
Goal placement(const World& world, ObjectId thing, ObjectId place) {
  const bool surface = world.universe->info(place).kind == ObjectKind::kSurface;
  return Goal({Literal{Fact(surface ? world.vocabulary.on : world.vocabulary.in, {thing, place}), true}});
}

}  // namespace

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_from_llm_placement(
    ObjectId object, ObjectReport& report) {
  LlmAdvisor& llm = *agent_.llm_;
  if (!llm.knows_preference_prompts() || !llm.asking()) return std::optional<Goal>();
  const World& w = world();
  if (!llm_preferences_.consulted()) {
    std::vector<ObjectId> things;
    for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
      if (o == object || still_to_come(o)) things.push_back(o);
    std::vector<GoalKnowledge> taught;
    for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
      if (g.key.task == progress_.task.name) taught.push_back(g);
    std::map<std::string, std::string> learned_as;
    for (const CategoryMatch& m : transfer_.matches()) learned_as[m.world] = m.learned;
    llm_preferences_.consult(llm, w, taught, learned_as, things, current().places, join(rules_said_, " "),
                             agent_.understanding_.lexicon());
    if (!llm_preferences_.summary().empty())
      spdlog::info("the LLM sums up what was taught: {}", llm_preferences_.summary());
  }
  auto place = llm_preferences_.place_for(object);
  if (!place) return std::optional<Goal>();
  Goal goal = placement(w, object, *place);
  const bool instructed = agent_.options_.condition.instruction;
  if (instructed) {
    auto yes = confirm(question(QuestionKind::kConfirmGoal, language::say_goal_question(w, object, goal, true), object, goal));
    if (!yes) return tl::unexpected(yes.error());
    if (!*yes) return std::optional<Goal>();
    say(language::read_back_goal(w, object, goal));
  }
  const std::string& by = llm_preferences_.placed_by();
  const std::string source = "llm placement" + (by.empty() ? std::string() : " by " + apprentice::quoted(by)) +
                             (instructed ? " (confirmed)" : "");
  if (auto s = learn_goal(object, goal, source); !s) return stop(s.error());
  report.goal_source = "llm";
  return std::optional<Goal>(goal);
}

}  // namespace apprentice
