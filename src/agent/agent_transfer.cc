// Goals by analogy across worlds (transfer.h): for a kind of object the
// agent knows no goal for, the goal of the nearest kind it learned before
// the session, proposed to the teacher or, alone, adopted when sure enough.
#include "agent/session.h"
#include "language/narration.h"
#include "util/log.h"

namespace apprentice {

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_by_analogy(
    ObjectId object, ObjectReport& report) {
  std::optional<Analogy> analogy = transfer_.analogy(world(), goal_key(object), object);
  if (!analogy) return std::optional<Goal>();
  const std::string like = "like the " + language::spoken_category(analogy->learned_as);
  const bool teacher = learning_ && agent_.options_.condition.instruction;
  if (teacher) {
    // A yes costs the teacher one yes/no answer; a no falls back to asking.
    auto yes = confirm(question(QuestionKind::kConfirmGoal, ask_analogy(world(), object, *analogy), object, analogy->goal));
    if (!yes) return tl::unexpected(yes.error());
    if (!*yes) return std::optional<Goal>();
    say(language::read_back_goal(world(), object, analogy->goal));
  } else if (analogy->confidence < kAdoptAnalogyAt) {
    if (!learning_) report.note = doubtful_analogy(*analogy);
    return std::optional<Goal>();
  }
  char confidence[16];
  std::snprintf(confidence, sizeof confidence, "%.2f", analogy->confidence);
  report_.analogies.push_back("took the goal of the " + analogy->learned_as + " for " + describe_object(object) +
                                   (teacher ? ", as the teacher confirmed" : std::string(", confidence ") + confidence));
  if (learning_) {
    std::string source = "analogy: " + like + (teacher ? " (confirmed)" : "");
    if (auto s = learn_goal(object, analogy->goal, source); !s) return stop(s.error());
  }
  report.goal_source = "analogy";
  return std::optional<Goal>(analogy->goal);
}

}  // namespace apprentice
