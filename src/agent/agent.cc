// Algorithm 1 as a loop of steps. next_step() reads how far the teaching
// has come and does what comes next:
//
//   no task yet                -> ask for the task (learn_task_name)
//   an object being worked on  -> act until its goal holds (achieve_current)
//   a subtask under way        -> its next object: the goal it knows for
//                                 that kind of object, or one it asks for
//                                 (start_object); or, the paper's way, ask
//                                 whether the subtask is done after its
//                                 first object (learn_subtask_end)
//   a known task's subtasks    -> do them, asking only what is new
//   otherwise                  -> ask for the task's next step
//                                 (learn_task_step)
#include "agent/agent.h"

#include <algorithm>
#include <set>

#include "agent/session.h"
#include "language/known_verbs.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "language/narration_steps.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

TaskLearningAgent::TaskLearningAgent(AgentOptions options, Knowledge knowledge, Understanding understanding,
                                     KnowledgeStore* store, LlmAdvisor* llm)
    : options_(std::move(options)), knowledge_(std::move(knowledge)), understanding_(std::move(understanding)),
      store_(store), llm_(llm) {
  APPRENTICE_CHECK_MSG(!options_.condition.llm || llm_ != nullptr, "an LLM condition needs an LLM");
}

Result<AgentReport> TaskLearningAgent::learn(Simulator& simulator, Dialogue& dialogue) {
  Session session(*this, simulator, &dialogue, true);
  return session.learn_task();
}

const TaskKnowledge* TaskLearningAgent::find_task(const std::string& name) const {
  if (const TaskKnowledge* task = knowledge_.find_task(name)) return task;
  if (name.empty()) return knowledge_.tasks.size() == 1 ? &knowledge_.tasks.front() : nullptr;
  return knowledge_.find_task(language::task_name_as_read(understanding_.lexicon(), name));
}

Result<AgentReport> TaskLearningAgent::perform(Simulator& simulator, const std::string& task_name) {
  Session session(*this, simulator, nullptr, false);  // first: it may rename what is known (transfer.h)
  const TaskKnowledge* task = find_task(task_name);
  if (task == nullptr)
    return make_error(ErrorCode::kNotFound, "no task '" + task_name + "' has been learned");
  return session.perform_task(*task);
}

TaskLearningAgent::Session::Session(TaskLearningAgent& agent, Simulator& simulator, Dialogue* dialogue,
                                    bool learning)
    : agent_(agent), simulator_(simulator), conversation_(dialogue), learning_(learning),
      lessons_(agent.store_, *simulator.world().domain),
      sources_(agent.knowledge_, simulator.world(), agent.understanding_.lexicon(), agent.understanding_.vectors()) {
  for (const CategoryMatch& m : sources_.transfer().matches())
    report_.renamed.push_back("took the " + m.world + " for the " + m.learned + " (" + m.reason + ")");
}

std::string TaskLearningAgent::Session::describe_object(ObjectId object) const {
  return world().universe->name(object) + " (" + world().universe->info(object).category + ")";
}

Result<AgentReport> TaskLearningAgent::Session::learn_task() {
  if (std::string renamed = say_renamings(sources_.transfer().matches()); !renamed.empty()) say(renamed);
  while (!progress_.finished) {
    Step step = next_step();
    // An undo has put everything back as it was before the last lesson:
    // the loop goes on from there.
    if (!step && step.error().error) {
      // Stopped (quit, end of input): what was learned is kept, its
      // induced rules too.
      if (auto kept = keep_induced_rules_learned(); !kept) spdlog::warn("{}", kept.error().message);
      return tl::unexpected(*step.error().error);
    }
  }
  if (auto kept = keep_induced_rules_learned(); !kept) return tl::unexpected(kept.error());
  report_.goals_learned = progress_.goals_learned;
  report_.rules_learned = progress_.rules_learned;
  return finished_report();
}

Result<AgentReport> TaskLearningAgent::Session::perform_task(const TaskKnowledge& task) {
  progress_.task = task;
  progress_.known_to_do.assign(task.subtasks.begin(), task.subtasks.end());
  while (!progress_.finished) {
    Step step = next_step();
    if (!step) return tl::unexpected(step.error().error.value_or(Error{ErrorCode::kCancelled, "stopped"}));
  }
  return finished_report();
}

AgentReport TaskLearningAgent::Session::finished_report() const {
  AgentReport report = report_;
  report.objects = progress_.objects;
  const ActingCounts& acted = actor_.counts();
  report.searches += acted.searches;
  report.search_nodes += acted.search_nodes;
  report.rule_actions += acted.rule_actions;
  report.actions_executed += acted.actions_executed;
  report.task_finished = true;
  return report;
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::next_step() {
  switch (progress_.next(learning_)) {
    case teaching::Next::kAchieve: return achieve_current();
    case teaching::Next::kAskTaskName: return learn_task_name();
    case teaching::Next::kNextObject:
      if (auto object = next_object(current())) return start_object(*object);
      finish_subtask();
      return {};
    case teaching::Next::kAskSubtaskEnd: return learn_subtask_end();
    case teaching::Next::kAskTaskStep: return learn_task_step();
    case teaching::Next::kStartKnownSubtask: return start_known_subtask();
    case teaching::Next::kFinish: progress_.finished = true; return {};
  }
  return {};
}

// --- The task and its structure ---------------------------------------------

namespace {

// A known task with the verb of `name` over a room whose name ends the
// other's: "tidy gym" for "tidy garage gym" (taught in the gym, said in the
// garage gym), "tidy home office" for "tidy office"; not "tidy dorm room"
// for "tidy living room". nullptr when there is none.
const TaskKnowledge* task_over_a_room_like(const Knowledge& knowledge, const std::string& name) {
  const std::vector<std::string> said = split_words(name);
  if (said.size() < 2) return nullptr;
  // Whether the room words of `task` (after its verb) end `whole`'s words.
  auto ends = [](const std::vector<std::string>& whole, const std::vector<std::string>& task) {
    const std::size_t room = task.size() - 1;
    return room > 0 && room <= whole.size() &&
           std::equal(task.begin() + 1, task.end(), whole.end() - static_cast<std::ptrdiff_t>(room));
  };
  for (const TaskKnowledge& task : knowledge.tasks) {
    const std::vector<std::string> known = split_words(task.name);
    if (known.size() < 2 || known.front() != said.front()) continue;
    if (ends(known, said) || ends(said, known)) return &task;
  }
  return nullptr;
}

}  // namespace

TaskLearningAgent::Session::Step TaskLearningAgent::Session::learn_task_name() {
  auto heard = converse(question(QuestionKind::kTaskName, language::ask_task()), context(language::Asked::kTask),
                        [](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::TaskNamed>(r)) return std::nullopt;
                          return language::need_task_name_first();
                        });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply)
    return stop(Error{ErrorCode::kInvalidInput,
                      "the instructor's replies could not be understood: " + apprentice::quoted(heard->text)});
  begin_lesson(heard->text);
  // ("tidy the office" in a home office is "tidy home office": the reader
  // names the task by the room, language/reply_task.cc.)
  std::string name = std::get<language::TaskNamed>(*heard->reply).name;
  if (!agent_.knowledge_.find_task(name))
    if (const TaskKnowledge* like = task_over_a_room_like(agent_.knowledge_, name)) name = like->name;
  if (const TaskKnowledge* known = agent_.knowledge_.find_task(name)) {
    progress_.task = *known;
    progress_.known_to_do.assign(known->subtasks.begin(), known->subtasks.end());
    progress_.asked_about_task = !known->subtasks.empty();
    say(language::already_know_task(name));
    return {};
  }
  progress_.task = TaskKnowledge{name, {}};
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::learn_task_step() {
  using language::Reply;
  const bool awaiting_repeat = progress_.current && progress_.current->mode == Current::Mode::kAwaitRepeat;
  Question asked = question(QuestionKind::kTaskStep, language::ask_task_step(progress_.task.name, !progress_.asked_about_task));
  auto heard = converse(asked, context(language::Asked::kTaskStep), [&](const Reply& r) -> std::optional<std::string> {
    if (std::holds_alternative<language::LoopNamed>(r) || std::holds_alternative<language::SubtaskNamed>(r))
      return std::nullopt;
    // "the notebook goes on the bookshelf": a correction of a kind taught.
    if (thing_corrected(r)) return std::nullopt;
    // "we're done" before any part of the task was taught would end the
    // lesson having learned nothing, and call the task learned.
    if (std::holds_alternative<language::Finished>(r))
      return progress_.task.subtasks.empty() && !progress_.current
                 ? std::optional<std::string>(language::no_part_taught_yet())
                 : std::nullopt;
    if (std::holds_alternative<language::Proceed>(r))
      return awaiting_repeat ? std::nullopt : std::optional<std::string>(language::nothing_to_repeat_yet());
    return language::asked_for_next_step();
  });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply)
    return stop(Error{ErrorCode::kInvalidInput,
                      "the instructor's replies could not be understood: " + apprentice::quoted(heard->text)});
  begin_lesson(heard->text);
  progress_.asked_about_task = true;
  const Reply& reply = *heard->reply;
  // A loop that was announced runs before anything else is begun.
  if (awaiting_repeat) progress_.loop();
  if (const auto* loop = std::get_if<language::LoopNamed>(&reply)) {
    progress_.announced_loop = loop->places;
    say(language::read_back_loop(world(), loop->places));
    return {};
  }
  if (const auto* subtask = std::get_if<language::SubtaskNamed>(&reply)) return start_subtask(*subtask);
  if (const auto* given = std::get_if<language::GoalGiven>(&reply))
    if (const std::optional<ObjectId> thing = thing_corrected(reply)) {
      if (auto s = correct_goal(*thing, *given, heard->text); !s) return stop(s.error());
      return {};
    }
  if (std::holds_alternative<language::Finished>(reply)) {
    progress_.finishing = true;
    say(language::read_back_task_done(progress_.current.has_value()));
    return {};
  }
  // Proceed: the loop runs (set above).
  say(language::read_back_the_rest_the_same_way(progress_.current->verb, progress_.current->relation, world(),
                                                 progress_.current->places));
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::start_subtask(const language::SubtaskNamed& named) {
  // Naming the next subtask ends the one under way, once its loop is done.
  const Current next =
      progress_.subtask_named(Current{named.verb, std::string(language::to_string(named.relation)), named.places});
  LearnedSubtask learned{next.verb, next.relation, world().universe->info(next.places.front()).category};
  if (std::find(progress_.task.subtasks.begin(), progress_.task.subtasks.end(), learned) ==
      progress_.task.subtasks.end()) {
    progress_.task.subtasks.push_back(learned);
    if (auto s = remember_task(); !s) return stop(s.error());
  }
  say(language::read_back_part(next.verb, next.relation, world(), next.places,
                               next.mode == Current::Mode::kFirstObject));
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::learn_subtask_end() {
  using language::Reply;
  const Current& c = current();
  Question asked = question(QuestionKind::kSubtaskStep, language::ask_subtask_end(c.verb, world(), c.places));
  auto heard = converse(asked, context(language::Asked::kSubtaskEnd), [](const Reply& r) -> std::optional<std::string> {
    if (std::holds_alternative<language::Finished>(r) || std::holds_alternative<language::Proceed>(r) ||
        std::holds_alternative<language::SubtaskNamed>(r))
      return std::nullopt;
    return language::asked_whether_more_to_part();
  });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) {
    // A program that cannot say: take the subtask as done, as it was.
    progress_.one_was_all();
    return {};
  }
  begin_lesson(heard->text);
  if (std::holds_alternative<language::Finished>(*heard->reply)) {
    progress_.one_was_all();
    say(language::read_back_one_was_all(c.verb));
    return {};
  }
  if (const auto* subtask = std::get_if<language::SubtaskNamed>(&*heard->reply)) return start_subtask(*subtask);
  progress_.loop();
  say(language::read_back_the_rest_the_same_way(c.verb, c.relation, world(), c.places));
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::start_known_subtask() {
  LearnedSubtask subtask = progress_.known_to_do.front();
  progress_.known_to_do.pop_front();
  std::vector<ObjectId> places = world().universe->with_category(subtask.place_category);
  if (places.empty()) {
    if (learning_)
      say(language::no_place_for_known_part(subtask.place_category, subtask.verb));
    else
      report_.help_needed.push_back("which " + language::spoken_category(subtask.place_category) + " to " +
                                    subtask.verb + ": there is none here");
    return {};
  }
  progress_.current = Current{subtask.verb, subtask.relation, places, Current::Mode::kLoop};
  return {};
}

Status TaskLearningAgent::Session::remember_task() { return lessons_.learn_task(agent_.knowledge_, progress_.task); }

// --- Subtasks and their objects ----------------------------------------------

namespace {

// The things (not furniture) on or in `places`.
size_t items_at(const World& world, const std::vector<ObjectId>& places) {
  size_t count = 0;
  for (PredicateId predicate : {world.vocabulary.on, world.vocabulary.in})
    for (ObjectId place : places)
      for (const Fact& f : world.state.facts_with_second(predicate, 2, place))
        if (world.universe->info(f.args[0]).kind == ObjectKind::kItem) ++count;
  return count;
}

}  // namespace

void TaskLearningAgent::Session::finish_subtask() {
  const Current& c = current();
  if (learning_) {
    // Objects the agent could not tidy are still there: saying "nothing
    // left" would be false (issue 25: 30 of 30 were still on the table).
    // Things the teacher said to leave were read back then ("I will leave
    // ...", "So I leave ..."), and are not failures.
    // So are the things it put there for this time only, as told.
    auto here = [&](ObjectId o) {
      std::optional<ObjectId> at = language::place_of(world(), o);
      return at && std::find(c.places.begin(), c.places.end(), *at) != c.places.end();
    };
    const long long left =
        static_cast<long long>(std::count_if(progress_.left_by_teacher.begin(), progress_.left_by_teacher.end(), here) +
                               std::count_if(progress_.placed_this_time.begin(), progress_.placed_this_time.end(), here));
    const long long remaining = static_cast<long long>(items_at(world(), c.places)) - left;
    if (remaining == 0 && left == 0)
      say(language::nothing_left(c.relation, world(), c.places, c.mode == Current::Mode::kFirstObject));
    else if (remaining > 0)
      say(language::could_not_finish(c.verb, remaining, c.relation, world(), c.places));
  }
  progress_.subtask_done();
}

std::optional<ObjectId> TaskLearningAgent::Session::next_object(const Current& current) const {
  // The first (on|in ?x place) in the state's order, for the current places,
  // whose ?x was not evaluated yet: by predicate, then ?x. Found through the
  // state's index by second argument, not by scanning every fact.
  const Vocabulary& v = world().vocabulary;
  for (PredicateId predicate : {std::min(v.on, v.in), std::max(v.on, v.in)}) {
    std::optional<ObjectId> first;
    for (ObjectId place : current.places) {
      for (const Fact& f : world().state.facts_with_second(predicate, 2, place)) {
        if (first && f.args[0] >= *first) break;
        if (progress_.evaluated.count(f.args[0])) continue;
        first = f.args[0];
        break;
      }
    }
    if (first) return first;
  }
  return std::nullopt;
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::start_object(ObjectId object) {
  take_news();
  ObjectReport report;
  report.object = world().universe->name(object);
  report.subtask = current().verb;
  report.part_place = world().universe->info(current().places.front()).category;
  std::optional<Goal> goal;
  if (const GoalKnowledge* known = agent_.knowledge_.goals.find(goal_key(object))) {
    goal = instantiate_goal(world(), *known, object);
    if (goal) {
      report.goal_source = GoalSource::kMemory;
      if (learning_) say(language::announce_known_goal(world(), object, *goal));
    }
  }
  if (!goal) {
    auto analogous = goal_by_decision(object, report);
    if (!analogous) return tl::unexpected(analogous.error());
    goal = *analogous;
  }
  if (!goal && !learning_) {
    std::string doubt = report.note.empty() ? "" : ": " + report.note;
    report.note = "no goal known";
    report_.help_needed.push_back("where " + language::spoken_name_and_location(world(), object) + " goes (" +
                                  current().verb + ")" + doubt);
  } else if (!goal && !was_left_as_told(object)) {
    // (Left where it is at the teacher's word, "I'm done" or "leave it"
    // said at a proposed goal: nothing more to ask.)
    auto acquired = acquire_goal(object, report);
    if (!acquired) return tl::unexpected(acquired.error());
    goal = *acquired;
  }
  if (!goal) {
    progress_.in_progress = InProgress{object, Goal{}, report, world().state, {}, {}, {}};
    progress_.object_done();
    return {};
  }
  report.goal = format_goal(*world().domain, *world().universe, *goal);
  if (agent_.knowledge_.goals.find(goal_key(object)) != nullptr) progress_.last_goal = goal_key(object);
  progress_.in_progress = InProgress{object, *goal, report, world().state, {}, {}, {}};
  return {};
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::achieve_current() {
  InProgress& work = *progress_.in_progress;
  auto acted = actor_.achieve(world(), work, current().verb, acting_policy(), *this);
  if (!acted) return tl::unexpected(acted.error());
  work.report.achieved = *acted == Acted::kAchieved;
  if (*acted == Acted::kNoWay && !learning_)
    report_.help_needed.push_back(language::help_needed_for_goal_to_hold(world(), work.goal));
  if (work.report.achieved && learning_) {
    for (Rule& rule : rules_taught(world(), work, current().verb, describe_object(work.object),
                                   agent_.options_.generalization)) {
      auto learned = lessons_.learn_rule(agent_.knowledge_, std::move(rule));
      if (!learned) return stop(learned.error());
      if (*learned) ++progress_.rules_learned;
    }
  }
  if (learning_) {
    std::string done = language::report_actions(world(), work.actions);
    if (!done.empty()) say(done);
  }
  progress_.object_done();
  return {};
}

}  // namespace apprentice
