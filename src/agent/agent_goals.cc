// Acquiring goals: from the LLM (confirmed by the instructor where there is
// one) or from the instructor, and learning them as goal knowledge.
#include <algorithm>

#include "agent/goal_repair.h"
#include "agent/session.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "language/utterance.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

// An object's report when the teacher said to leave it.
constexpr std::string_view kLeftAsTold = "left where it is, as the instructor said";

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
  // The LLM's placement of the thing, where it gave one, was weighed in
  // the decision (agent_decision.cc) with the other sources.
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
// is asked (goal_from_instructor).
TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_from_llm(ObjectId object,
                                                                                              ObjectReport& report) {
  LlmAdvisor& llm = *agent_.llm_;
  const AgentOptions& options = agent_.options_;
  const GoalRepairOptions& repair = options.goal_repair;
  const bool instructed = options.condition.instruction;
  const bool repairing = format_goal_repair(repair) != "none";
  llm::TaskContext context = llm_context(object);
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
      say(language::could_not_reach_llm(llm.last_failure()->message, instructed));
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
    // model's own words when nothing is repaired or it does not ground. An
    // undo or the teacher leaving stops the choice (`stopped`).
    std::optional<Stop> stopped;
    llm::CallbackConfirmer confirmer([&](llm::QueryKind, const llm::Candidate& c) -> Result<bool> {
      const AnalysedGoal* analysed = analysis.find(c);
      const std::optional<Goal> goal = analysed ? analysed->goal : std::nullopt;
      std::string text = goal && repairing ? language::say_goal_question(world(), object, *goal, true)
                                           : language::say_goal_question(world(), object, c.text);
      auto yes = confirm(question(QuestionKind::kConfirmGoal, text, object, goal));
      if (yes) return *yes;
      stopped = yes.error();
      return make_error(ErrorCode::kCancelled, "the choice of an LLM goal was stopped");
    });
    auto choice = llm::finalize_choice(analysis.ordered_candidates(), llm::QueryKind::kGoal, usable,
                                       instructed ? &confirmer : nullptr, choosing);
    if (stopped) return tl::unexpected(*stopped);
    if (!choice) return stop(choice.error());
    if (choice->candidate) {
      const AnalysedGoal* chosen = analysis.find(*choice->candidate);
      if (chosen == nullptr || !chosen->goal) {
        // Without an instructor the most probable statement is taken as it
        // is (the paper's Search+LLM condition); one that cannot be used
        // fails the object.
        report.note = "LLM goal " + apprentice::quoted(choice->text) + " is unusable: " +
                      (chosen ? std::string(to_string(chosen->failure_kind)) : std::string("ungrounded"));
        return std::optional<Goal>();
      }
      if (instructed) say(language::read_back_goal(world(), object, *chosen->goal));
      std::string repairs = describe_repairs(world(), *chosen);
      std::string source = std::string(choice->candidate->source == llm::ResponseSource::kCorpus ? "corpus" : "llm") +
                           ": " + apprentice::quoted(choice->text) + (repairs.empty() ? "" : " (" + repairs + ")") +
                           (instructed ? " (confirmed)" : "");
      if (auto s = learn_goal(object, *chosen->goal, source); !s) return stop(s.error());
      report.goal_source = GoalSource::kLlm;
      return chosen->goal;
    }
    // Nothing accepted: the failure context of the next query.
    for (const llm::Candidate& candidate : candidates) context.rejected.push_back(candidate.text);
  }
  if (!instructed && report.note.empty()) report.note = "no usable LLM goal";
  return std::optional<Goal>();
}

TaskLearningAgent::Session::Flow<std::optional<Goal>> TaskLearningAgent::Session::goal_from_instructor(
    ObjectId object, ObjectReport& report) {
  const World& w = world();
  Question asked = question(QuestionKind::kSubtaskStep, language::ask_goal(w, object), object);
  // A person may say where another thing of this subtask goes before being
  // asked about it ("the sweater goes on the low shelf", asked about the
  // sock): that goal is learned for its kind, and the question comes again.
  for (;;) {
    std::optional<ObjectId> ahead;
    // "actually the kneeling pad should hang on the left hook", asked about
    // another thing: a correction of a thing already dealt with, made, and
    // the question asked again.
    std::optional<ObjectId> corrected;
    auto heard = converse(
        asked, context(language::Asked::kGoal, object),
        [&](const language::Reply& r) -> std::optional<std::string> {
          corrected = thing_corrected(r);
          if (corrected && *corrected != object) return std::nullopt;
          corrected.reset();
          return why_not_a_goal_for(object, r, ahead);
        },
        [&](const std::string& text) { return goal_for_another(object, text); });
    if (!heard) return tl::unexpected(heard.error());
    if (corrected && heard->reply) {
      begin_lesson(heard->text);
      if (auto s = correct_goal(*corrected, std::get<language::GoalGiven>(*heard->reply), heard->text); !s)
        return stop(s.error());
      continue;
    }
    if (heard->rule_heard) {
      // A person's rule said instead of where this thing goes: it is
      // weighed with the other sources first (it may place the thing, or
      // make a yes/no of the question); else the question comes again.
      auto decided = goal_by_decision(object, report);
      if (!decided || *decided || was_left_as_told(object)) return decided;
      continue;
    }
    if (!heard->reply) {
      // Given up on after refused replies: said in the report, with them.
      report.note = "no usable goal from the instructor";
      report_.help_needed.push_back(language::help_needed_for_goal(w, object, current().verb, heard->refused));
      return std::optional<Goal>();
    }
    if (const auto* ended = std::get_if<language::Finished>(&*heard->reply)) {
      auto left = leave_as_told(object, *ended, heard->text, report);
      if (!left) return tl::unexpected(left.error());
      if (!*left) continue;  // "no" to leaving the rest: the question again
      return std::optional<Goal>();
    }
    begin_lesson(heard->text);
    const ObjectId about = ahead.value_or(object);
    bool say_norm = false;
    const language::GoalGiven given = with_doors_closed(about, std::get<language::GoalGiven>(*heard->reply), say_norm);
    const std::string source = "instructor: " + apprentice::quoted(heard->text);
    say((ahead ? language::read_back_goal_for_later(w, about, given.goal) : language::read_back_goal(w, about, given.goal)) +
        (say_norm ? " " + language::closing_norm_note() : ""));
    // "just for tonight, the locker": done now, not learned for the kind.
    if (given.this_time_only && !ahead) {
      say(language::this_time_only_note());
      progress_.placed_this_time.push_back(object);
      report.goal_source = GoalSource::kInstructor;
      return std::optional<Goal>(given.goal);
    }
    if (auto s = learn_goal(about, given.goal, source); !s) return stop(s.error());
    if (auto s = learn_goals_of_others(object, about, given, heard->text, source); !s) return stop(s.error());
    if (ahead) continue;
    report.goal_source = GoalSource::kInstructor;
    return std::optional<Goal>(given.goal);
  }
}

bool TaskLearningAgent::Session::was_left_as_told(ObjectId object) const {
  const std::vector<ObjectId>& left = progress_.left_by_teacher;
  return std::find(left.begin(), left.end(), object) != left.end();
}

TaskLearningAgent::Session::Flow<bool> TaskLearningAgent::Session::leave_as_told(ObjectId object,
                                                                                const language::Finished& ended,
                                                                                const std::string& text,
                                                                                ObjectReport& report) {
  if (ended.ending && asked_to_leave_the_rest_.insert(object).second) {
    auto left = ask_to_leave_the_rest(object);
    if (!left) return tl::unexpected(left.error());
    if (left->has_value() && !**left) return false;
    if (left->has_value()) {
      report.note = kLeftAsTold;
      return true;
    }
    // Nothing else to come: the ending leaves this thing, as "leave it" does.
  }
  begin_lesson(text);
  report.note = kLeftAsTold;
  progress_.thing_left(object);
  say(language::will_leave_as_it_is(world(), object, true));
  return true;
}

std::optional<std::string> TaskLearningAgent::Session::why_not_a_goal_for(
    ObjectId object, const language::Reply& reply, std::optional<ObjectId>& ahead) const {
  const World& w = world();
  ahead.reset();
  if (std::holds_alternative<language::Finished>(reply)) return std::nullopt;
  const auto* given = std::get_if<language::GoalGiven>(&reply);
  if (given == nullptr) return language::asked_where_it_goes(w, object);
  std::vector<ObjectId> mentioned = given->goal.objects();
  if (std::find(mentioned.begin(), mentioned.end(), object) != mentioned.end()) return std::nullopt;
  std::vector<ObjectId> items;
  for (ObjectId o : mentioned)
    if (w.universe->info(o).kind == ObjectKind::kItem) items.push_back(o);
  if (items.size() == 1 && progress_.still_to_come(world(), items.front())) {
    ahead = items.front();
    return std::nullopt;
  }
  // A goal about something else is never stored as this one's.
  return language::says_what_becomes_of_others(w, items, object);
}

TaskLearningAgent::Session::Flow<std::optional<bool>> TaskLearningAgent::Session::ask_to_leave_the_rest(
    ObjectId object) {
  const World& w = world();
  std::vector<ObjectId> rest;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (o != object && progress_.still_to_come(world(), o)) rest.push_back(o);
  if (rest.empty()) return std::optional<bool>();
  std::vector<ObjectId> things = {object};
  things.insert(things.end(), rest.begin(), rest.end());
  const Current part = current();
  auto yes =
      confirm(question(QuestionKind::kConfirm, language::ask_leave_the_rest(w, things, part.places), object));
  if (!yes) return tl::unexpected(yes.error());
  if (!*yes) {
    say(language::read_back_going_on(w, object));
    return std::optional<bool>(false);
  }
  say(language::read_back_part_left(w, things, part.places));
  std::vector<std::pair<ObjectId, ObjectReport>> left;
  for (ObjectId o : rest) {
    ObjectReport as_left;
    as_left.object = w.universe->name(o);
    as_left.subtask = part.verb;
    as_left.part_place = w.universe->info(part.places.front()).category;
    as_left.note = kLeftAsTold;
    left.emplace_back(o, std::move(as_left));
  }
  progress_.part_left(object, left);
  return std::optional<bool>(true);
}

std::optional<language::Reply> TaskLearningAgent::Session::goal_for_another(ObjectId object,
                                                                            const std::string& text) const {
  // Read as if nothing had been asked: the reply's own thing is the one it
  // places.
  language::Reply reply = agent_.understanding_.reply(world(), context(language::Asked::kGoal, std::nullopt), text);
  const auto* given = std::get_if<language::GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  std::vector<ObjectId> items;
  for (ObjectId o : given->goal.objects())
    if (world().universe->info(o).kind == ObjectKind::kItem) items.push_back(o);
  if (items.size() != 1 || items.front() == object || progress_.evaluated.count(items.front())) return std::nullopt;
  if (progress_.still_to_come(world(), items.front())) return reply;
  // Not in this subtask's places: its subtask is not known yet.
  const ObjectId other = items.front();
  return language::Reply(language::Unusable{
      language::will_ask_about_later(world(), other, {current().verb, current().relation, current().places}, object),
      agent_.understanding_.example_replies(world(), context(language::Asked::kGoal, object)), std::nullopt});
}

language::GoalGiven TaskLearningAgent::Session::with_doors_closed(ObjectId about, language::GoalGiven given,
                                                                  bool& say_norm) {
  const World& w = world();
  bool by_norm = false;
  auto close = [&](ObjectId object, Goal& goal) {
    const std::vector<ClosingToAdd> closings =
        closings_to_complete(w, goal, object, agent_.knowledge_.goals, progress_.doors_left_open);
    if (closings.empty()) return;
    goal = with_closings(w, goal, closings);
    by_norm = by_norm || std::any_of(closings.begin(), closings.end(), [](const ClosingToAdd& c) { return c.by_norm; });
  };
  close(about, given.goal);
  for (Goal& other : given.others) {
    std::vector<ObjectId> items;
    for (ObjectId o : other.objects())
      if (w.universe->info(o).kind == ObjectKind::kItem) items.push_back(o);
    if (items.size() == 1) close(items.front(), other);
  }
  say_norm = by_norm && !closing_norm_said_;
  closing_norm_said_ = closing_norm_said_ || by_norm;
  return given;
}

Status TaskLearningAgent::Session::learn_goals_of_others(ObjectId asked, ObjectId about, const language::GoalGiven& given,
                                                        const std::string& text, const std::string& source) {
  const World& w = world();
  std::vector<ObjectId> same, learned, later;
  // Things dealt with already whose goal the reply corrects ("and the pen
  // too, pens aren't books", after the pen went on the bookshelf).
  std::vector<std::pair<ObjectId, Goal>> corrected;
  for (const Goal& goal : given.others) {
    std::vector<ObjectId> items;
    for (ObjectId o : goal.objects())
      if (w.universe->info(o).kind == ObjectKind::kItem) items.push_back(o);
    if (items.size() != 1 || items.front() == asked || items.front() == about) continue;
    const ObjectId item = items.front();
    if (!progress_.still_to_come(world(), item)) {
      if (!progress_.evaluated.count(item)) later.push_back(item);
      else if (!goals_corrected_by(item, {}).empty() && !goal.satisfied_by(w.state)) corrected.emplace_back(item, goal);
      continue;
    }
    if (auto s = learn_goal(item, goal, source); !s) return s;
    learned.push_back(item);
    // "The same goes for ...": the goal asked for, with this thing in its place.
    auto as_asked = [&](Literal l) {
      for (std::size_t i = 0; i < l.fact.arity; ++i)
        if (l.fact.args[i] == item) l.fact.args[i] = about;
      return l;
    };
    bool alike = goal.literals.size() == given.goal.literals.size() &&
                 std::equal(goal.literals.begin(), goal.literals.end(), given.goal.literals.begin(),
                            [&](const Literal& a, const Literal& b) { return as_asked(a) == b; });
    if (alike) same.push_back(item);
    else say(language::read_back_goal(w, item, goal));
  }
  for (const std::string& line : language::goals_for_others(w, same, learned, later)) say(line);
  for (const auto& [item, goal] : corrected) {
    language::GoalGiven correction;
    correction.goal = goal;
    if (auto s = correct_goal(item, correction, text); !s) return s;
  }
  return {};
}

Status TaskLearningAgent::Session::learn_goal(ObjectId object, const Goal& goal, const std::string& source,
                                              const std::optional<GoalKey>& key) {
  // What "the door" and "close it" mean next: the place this goal names.
  for (const Literal& l : goal.literals)
    if ((l.fact.predicate == world().vocabulary.in || l.fact.predicate == world().vocabulary.on) && l.fact.arity == 2 &&
        l.fact.args[0] == object)
      conversation_.named_place(l.fact.args[1]);
  auto knowledge =
      generalize_goal(world(), key ? *key : goal_key(object), object, goal, Provenance{describe_object(object), source});
  if (!knowledge) {
    // Still usable for this object, just not learnable for its category.
    spdlog::warn("goal not learned: {}", knowledge.error().message);
    return {};
  }
  progress_.last_goal = knowledge->key;
  ++progress_.goals_learned;
  return lessons_.learn_goal(agent_.knowledge_, *knowledge);
}

std::vector<GoalKey> TaskLearningAgent::Session::goals_corrected_by(ObjectId object,
                                                                  const std::vector<std::string>& properties) const {
  const std::string& kind = world().universe->info(object).category;
  const std::vector<ObjectId> things = progress_.dealt_with_like(world(), object, properties);
  if (things.empty()) return {};
  // "the clean diapers go in the bottom drawer": only the parts the clean
  // ones were dealt with in, not the floor's dirty diaper.
  std::vector<GoalKey> keys;
  if (!properties.empty()) {
    for (ObjectId thing : things)
      if (std::optional<GoalKey> key = key_dealt_with(thing); key && std::find(keys.begin(), keys.end(), *key) == keys.end())
        keys.push_back(*key);
    return keys;
  }
  for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
    if (g.key.task == progress_.task.name && g.key.category == kind) keys.push_back(g.key);
  // Its goal forgotten since ("forget the stapler"): the goal comes anew
  // under the part of the task it was dealt with in.
  if (keys.empty())
    if (std::optional<GoalKey> key = key_dealt_with(things.back())) keys.push_back(*key);
  return keys;
}

std::optional<GoalKey> TaskLearningAgent::Session::key_dealt_with(ObjectId thing) const {
  const std::string& kind = world().universe->info(thing).category;
  const std::string& name = world().universe->name(thing);
  const ObjectReport* dealt = nullptr;
  for (const ObjectReport& report : progress_.objects)
    if (report.object == name) dealt = &report;
  if (dealt == nullptr || dealt->subtask.empty()) return std::nullopt;
  if (!dealt->part_place.empty()) return GoalKey{progress_.task.name, dealt->subtask, kind, dealt->part_place};
  // The part under way, else the last part learned, with that verb.
  std::optional<std::string> place;
  if (progress_.current && progress_.current->verb == dealt->subtask && !progress_.current->places.empty())
    place = world().universe->info(progress_.current->places.front()).category;
  for (auto part = progress_.task.subtasks.rbegin(); !place && part != progress_.task.subtasks.rend(); ++part)
    if (part->verb == dealt->subtask) place = part->place_category;
  if (!place) return std::nullopt;
  return GoalKey{progress_.task.name, dealt->subtask, kind, *place};
}

std::optional<ObjectId> TaskLearningAgent::Session::thing_corrected(const language::Reply& reply) const {
  const auto* given = std::get_if<language::GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  for (ObjectId o : given->goal.objects())
    if (world().universe->info(o).kind == ObjectKind::kItem)
      return goals_corrected_by(o, {}).empty() ? std::nullopt : std::optional<ObjectId>(o);
  return std::nullopt;
}

Status TaskLearningAgent::Session::correct_goal(ObjectId object, const language::GoalGiven& said,
                                               const std::string& text) {
  const World& w = world();
  bool say_norm = false;
  const language::GoalGiven given = with_doors_closed(object, said, say_norm);
  const std::string source = "instructor: " + apprentice::quoted(text) + " (a correction)";
  // "the clean diapers": the properties said pick the things and parts.
  // The things moved go where it now says, by the agent's own search; what
  // was closed is closed again after.
  std::vector<Literal> closed_before;
  for (ObjectId place : w.universe->of_kind(ObjectKind::kReceptacle))
    if (const Fact closed(w.vocabulary.closed, {place}); w.state.holds(closed)) closed_before.push_back(Literal{closed, true});
  std::vector<Action> done;
  auto move = [&](ObjectId thing, const Goal& placed) {
    std::vector<Literal> literals = placed.literals;
    literals.insert(literals.end(), closed_before.begin(), closed_before.end());
    const Goal goal(std::move(literals));
    OwnActions own;
    OwnActions::Ways ways;
    ways.unbounded_search = true;
    for (int steps = 0; !goal.satisfied_by(world().state) && steps < agent_.options_.max_actions_per_object; ++steps) {
      OwnActions::Next next = own.next(world(), goal, thing, "", ways);
      if (!next.action || !execute(*next.action)) break;
      done.push_back(*next.action);
    }
  };
  // "the blanket goes on the sofa, its cold tonight": this thing is moved,
  // and nothing is learned.
  if (given.this_time_only) {
    say(language::read_back_goal(w, object, given.goal) + " " + language::this_time_only_note());
    progress_.placed_this_time.push_back(object);
    move(object, given.goal);
    if (!done.empty()) say(language::report_actions(w, done), Voice::kResponse);
    return {};
  }
  std::erase(progress_.placed_this_time, object);  // where it goes for good, said again
  const std::vector<std::string> properties = language::properties_said(*w.universe, object, text);
  const std::vector<GoalKey> keys = goals_corrected_by(object, properties);
  for (const GoalKey& key : keys)
    if (auto s = learn_goal(object, given.goal, source, key); !s) return s;
  say(language::read_back_goal(w, object, given.goal) + (say_norm ? " " + language::closing_norm_note() : ""));
  const GoalKnowledge* learned = keys.empty() ? nullptr : agent_.knowledge_.goals.find(keys.back());
  if (learned == nullptr) return learn_goals_of_others(object, object, given, text, source);
  for (ObjectId thing : progress_.dealt_with_like(w, object, properties))
    if (std::optional<Goal> placed = instantiate_goal(w, *learned, thing)) move(thing, *placed);
  if (!done.empty()) say(language::report_actions(w, done), Voice::kResponse);
  // "the jeans go in the hamper and the dirty towel goes in the washer":
  // the others said with it, corrected or learned too.
  return learn_goals_of_others(object, object, given, text, source);
}

}  // namespace apprentice
