#include "agent/teacher_questions.h"

#include <algorithm>
#include <optional>

#include "agent/explanation.h"
#include "agent/goal_repair.h"
#include "language/generation.h"
#include "language/narration_conversation.h"
#include "language/utterance.h"
#include "util/text.h"

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
  const std::vector<ObjectId>& for_now = so_far.progress.placed_this_time;
  if (std::find(for_now.begin(), for_now.end(), thing) != for_now.end())
    return language::placed_this_time_only(w, thing);
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
  if (!closed && so_far.progress.doors_left_open.count(door_key(w, place)))
    return language::door_left_open_as_told(w, place);
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

// How a thing's goal was come by, as the answer to "why" says it.
std::string how_decided(GoalSource source) {
  switch (source) {
    case GoalSource::kInstructor: return "as you told me then";
    case GoalSource::kMemory: return "as I had learned before";
    case GoalSource::kAnalogy: return "by analogy with a thing you taught me";
    case GoalSource::kLikeness: return "because it is like things you taught me";
    case GoalSource::kRule: return "by a rule I drew from what you taught me";
    case GoalSource::kPersonRule: return "by a rule you said";
    case GoalSource::kLlm: return "as the language model suggested";
    case GoalSource::kFleet: return "as other households do";
    case GoalSource::kDecision: return "weighing what you taught me";
    case GoalSource::kNone: break;
  }
  return "";
}

// "why did you put the water bottle in the wastebasket?", where it no
// longer goes, or "why'd you throw out the bottle before?": how it came to
// go to `place` (with none, where it went) when it was dealt with, and
// where it goes now; nullopt when its report does not put it there, or its
// goal still does.
std::optional<std::string> why_earlier(const TeachingSoFar& so_far, ObjectId thing, std::span<const ObjectId> places) {
  const World& w = so_far.world;
  const GoalKnowledge* known = goal_known_for(so_far, w.universe->info(thing).category);
  std::optional<Goal> now = known ? instantiate_goal(w, *known, thing) : std::nullopt;
  if (!now) return std::nullopt;
  const std::vector<ObjectId> now_at = destinations(w, *now, thing);
  auto now_goes = [&](ObjectId p) { return std::find(now_at.begin(), now_at.end(), p) != now_at.end(); };
  // ("why did you put the glove in the right basket", where it goes now:
  // not about before.)
  if (!places.empty() && std::all_of(places.begin(), places.end(), now_goes)) return std::nullopt;
  const std::string& name = w.universe->name(thing);
  for (const ObjectReport& report : so_far.progress.objects) {
    if (report.object != name || report.goal.empty()) continue;
    auto then = parse_goal(*w.domain, *w.universe, report.goal);
    if (!then) continue;
    const std::vector<ObjectId> then_at = destinations(w, *then, thing);
    const bool went_there = !places.empty() ? std::any_of(then_at.begin(), then_at.end(),
                                                          [&](ObjectId p) {
                                                            return std::find(places.begin(), places.end(), p) !=
                                                                   places.end();
                                                          })
                                            : !then_at.empty() && std::none_of(then_at.begin(), then_at.end(), now_goes);
    // (Where it still goes is no "before".)
    if (!went_there || std::all_of(then_at.begin(), then_at.end(), now_goes)) continue;
    const std::string how = report.because.empty() ? how_decided(report.goal_source) : report.because;
    return language::why_earlier_placement(w, thing, *then, how, *now);
  }
  return std::nullopt;
}

// "why did you ask if the blanket goes with clean diapers?": the last yes/no
// about a thing named, else about a thing of a kind named, else one whose
// evidence names a kind named ("why do you keep asking about diapers"),
// else, with no thing named, the last one asked; nullopt when none fits (a
// thing named that was never asked about is answered as "why" is).
std::optional<std::string> why_asked(const TeachingSoFar& so_far, std::span<const ObjectId> named) {
  const World& w = so_far.world;
  if (so_far.asked.empty()) return std::nullopt;
  auto last_where = [&](auto&& fits) -> const ProposalAsked* {
    for (auto it = so_far.asked.rbegin(); it != so_far.asked.rend(); ++it)
      if (fits(*it)) return &*it;
    return nullptr;
  };
  const ProposalAsked* asked = last_where([&](const ProposalAsked& a) {
    return std::find(named.begin(), named.end(), a.thing) != named.end();
  });
  if (asked == nullptr)
    asked = last_where([&](const ProposalAsked& a) {
      return std::any_of(named.begin(), named.end(), [&](ObjectId n) {
        return w.universe->info(n).category == w.universe->info(a.thing).category;
      });
    });
  if (asked == nullptr)
    asked = last_where([&](const ProposalAsked& a) {
      return std::any_of(named.begin(), named.end(), [&](ObjectId n) {
        return a.evidence.find(language::spoken_category(w.universe->info(n).category)) != std::string::npos;
      });
    });
  const bool things_named = std::any_of(named.begin(), named.end(), [&](ObjectId n) {
    return w.universe->info(n).kind == ObjectKind::kItem;
  });
  if (asked == nullptr && !things_named) asked = &so_far.asked.back();
  if (asked == nullptr) return std::nullopt;
  const GoalKnowledge* known = goal_known_for(so_far, w.universe->info(asked->thing).category);
  std::optional<Goal> now = known ? instantiate_goal(w, *known, asked->thing) : std::nullopt;
  if (now && *now == asked->goal) now.reset();
  return language::why_i_asked(w, asked->thing, asked->goal, asked->evidence, now);
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

std::string answer_why(const TeachingSoFar& so_far, std::span<const ObjectId> named, WhyAbout about) {
  const World& w = so_far.world;
  if (about == WhyAbout::kAsking)
    if (auto said = why_asked(so_far, named)) return *said;
  const bool earlier = about == WhyAbout::kEarlier;
  // A thing and a place named, the thing no longer going there. ("the
  // towel ... on the hook", of a clean and a dirty towel and two hooks:
  // the towel that went on a hook.)
  std::vector<ObjectId> places;
  for (ObjectId id : named)
    if (w.universe->info(id).kind != ObjectKind::kItem) places.push_back(id);
  if (!named.empty() && (earlier || !places.empty()) && w.universe->info(named.front()).kind == ObjectKind::kItem) {
    if (auto said = why_earlier(so_far, named.front(), places)) return *said;
    if (earlier)
      for (ObjectId alike : w.universe->with_category(w.universe->info(named.front()).category))
        if (alike != named.front())
          if (auto said = why_earlier(so_far, alike, places)) return *said;
  }
  // "why the hook at first": a place alone, asked about before; the thing
  // last put there that goes elsewhere now.
  if (earlier && !places.empty() && places.size() == named.size())
    for (auto report = so_far.progress.objects.rbegin(); report != so_far.progress.objects.rend(); ++report)
      if (const std::optional<ObjectId> thing = w.universe->find(report->object))
        if (auto said = why_earlier(so_far, *thing, places)) return *said;
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

std::string answer_whats_left(const TeachingSoFar& so_far) {
  const World& w = so_far.world;
  const teaching::Curriculum& progress = so_far.progress;
  if (!progress.current) {
    if (progress.task.name.empty()) return language::no_task_yet();
    std::vector<language::PartLearned> parts;
    for (const LearnedSubtask& s : progress.task.subtasks) parts.push_back({s.verb, s.relation, s.place_category});
    std::vector<ObjectId> not_dealt_with;
    for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
      if (!progress.evaluated.count(o)) not_dealt_with.push_back(o);
    return language::whats_left_of_task(w, parts, not_dealt_with);
  }
  std::vector<ObjectId> left;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (progress.still_to_come(w, o) && (!progress.in_progress || progress.in_progress->object != o)) left.push_back(o);
  const teaching::Current& part = *progress.current;
  return language::whats_left_of_subtask(w, {part.verb, part.relation, part.places}, left);
}

std::vector<std::string> answer_status(const TeachingSoFar& so_far, std::optional<ObjectId> asking_about,
                                       StatusCounts counts) {
  const World& w = so_far.world;
  const teaching::Curriculum& progress = so_far.progress;
  language::WhatIAmDoing doing;
  doing.task = progress.task.name;
  if (progress.current)
    doing.subtask = language::SubtaskUnderWay{progress.current->verb, progress.current->relation, progress.current->places};
  if (progress.in_progress) doing.working_on = progress.in_progress->object;
  doing.asking_about = asking_about;
  doing.goals = static_cast<long long>(so_far.goals.size());
  doing.rules = counts.rules;
  doing.instructions = counts.instructions;
  return {language::what_i_see(w), language::what_i_am_doing(w, doing)};
}

std::vector<std::string> kinds_known_by(const GoalMemory& goals, std::string_view phrase) {
  std::vector<std::string> words = split_words(to_lower(phrase));
  while (!words.empty() && language::is_determiner(words.front())) words.erase(words.begin());
  const std::string key = join(words, "-");
  const std::vector<std::string> forms = key.empty() ? std::vector<std::string>{} : singular_forms(key);
  std::vector<std::string> fits;
  for (const GoalKnowledge& g : goals.all()) {
    const std::string& c = g.key.category;
    const bool fit = std::any_of(forms.begin(), forms.end(), [&](const std::string& k) {
      return !k.empty() && (c == k || (c.size() > k.size() && c.ends_with("-" + k)));
    });
    if (fit && std::find(fits.begin(), fits.end(), c) == fits.end()) fits.push_back(c);
  }
  return fits;
}

}  // namespace apprentice
