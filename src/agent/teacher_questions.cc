#include "agent/teacher_questions.h"

#include <algorithm>
#include <optional>

#include "agent/explanation.h"
#include "language/generation.h"
#include "language/narration_conversation.h"

namespace apprentice {

namespace {

// Whether a goal's source is the agent's own decision, not confirmed by the
// teacher.
bool decided_alone(const std::string& source) {
  return (source.starts_with("decision: ") || source.starts_with("analogy: ") || source.starts_with("fleet: ")) &&
         !source.ends_with("(confirmed)");
}

bool left_by_teacher(const teaching::Curriculum& progress, ObjectId thing) {
  const std::vector<ObjectId>& left = progress.left_by_teacher;
  return std::find(left.begin(), left.end(), thing) != left.end();
}

// Why a thing is where it is: left as told, or its goal and where that came
// from; nullopt when no goal of its kind is known.
std::optional<std::string> why_thing(const TeachingSoFar& so_far, ObjectId thing) {
  const World& w = so_far.world;
  if (left_by_teacher(so_far.progress, thing)) return language::left_as_told(w, thing);
  const GoalKnowledge* known = goal_known_for(so_far, w.universe->info(thing).category);
  std::optional<Goal> goal = known ? instantiate_goal(w, *known, thing) : std::nullopt;
  if (!goal) return std::nullopt;
  const std::string& source = known->provenance.source;
  return decided_alone(source) ? language::because_i_decided(w, thing, explain_source(source))
                               : language::because_goal_from(w, thing, *goal, explain_source(source));
}

// Why a door is open or closed: open because the goal of a thing in it says
// to leave it so, or because nothing said to close it.
std::string why_door(const TeachingSoFar& so_far, ObjectId place) {
  const World& w = so_far.world;
  const bool closed = w.state.holds(Fact(w.vocabulary.closed, {place}));
  std::optional<std::pair<ObjectId, std::string>> left_open;
  for (ObjectId thing : w.universe->of_kind(ObjectKind::kItem)) {
    if (closed || left_open || language::place_of(w, thing) != place) continue;
    const GoalKnowledge* known = goal_known_for(so_far, w.universe->info(thing).category);
    std::optional<Goal> goal = known ? instantiate_goal(w, *known, thing) : std::nullopt;
    if (goal && std::any_of(goal->literals.begin(), goal->literals.end(), [&](const Literal& l) {
          return !l.positive && l.fact == Fact(w.vocabulary.closed, {place});
        }))
      left_open = std::make_pair(thing, explain_source(known->provenance.source));
  }
  return language::why_door_is(w, place, closed, left_open);
}

}  // namespace

const GoalKnowledge* goal_known_for(const TeachingSoFar& so_far, const std::string& kind) {
  const teaching::Curriculum& progress = so_far.progress;
  const GoalKnowledge* known = nullptr;
  if (progress.current) {
    const World& w = so_far.world;
    known = so_far.goals.find(GoalKey{progress.task.name, progress.current->verb, kind,
                                      w.universe->info(progress.current->places.front()).category});
  }
  for (const GoalKnowledge& g : so_far.goals.all())
    if (known == nullptr && g.key.category == kind && g.key.task == progress.task.name) known = &g;
  for (const GoalKnowledge& g : so_far.goals.all())
    if (known == nullptr && g.key.category == kind) known = &g;
  return known;
}

std::string answer_why(const TeachingSoFar& so_far, std::span<const ObjectId> named) {
  const World& w = so_far.world;
  for (ObjectId id : named) {
    if (w.universe->info(id).kind == ObjectKind::kItem) {
      if (auto said = why_thing(so_far, id)) return *said;
    } else if (w.state.holds(Fact(w.vocabulary.openable, {id}))) {
      return why_door(so_far, id);
    }
  }
  // The last goal learned came from the agent's own decision (a rule said,
  // things alike), not from the teacher's last reply: say so, and from what.
  const teaching::Curriculum& progress = so_far.progress;
  if (progress.last_goal && !progress.evaluated_order.empty())
    if (const GoalKnowledge* last = so_far.goals.find(*progress.last_goal)) {
      const ObjectId placed = progress.evaluated_order.back();
      if (decided_alone(last->provenance.source) && w.universe->info(placed).category == last->key.category)
        return language::because_i_decided(w, placed, explain_source(last->provenance.source));
    }
  return so_far.last_reply == nullptr ? language::why_without_a_reply()
                                      : language::because_of_last_reply(*so_far.last_reply);
}

}  // namespace apprentice
