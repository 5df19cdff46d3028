#include "agent/agent.h"

#include <algorithm>

#include "agent/session.h"
#include "language/generation.h"
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

Result<AgentReport> TaskLearningAgent::perform(Simulator& simulator, const std::string& task_name) {
  const TaskKnowledge* task = knowledge_.find_task(task_name);
  if (task == nullptr && task_name.empty() && knowledge_.tasks.size() == 1) task = &knowledge_.tasks.front();
  if (task == nullptr)
    return make_error(ErrorCode::kNotFound, "no task '" + task_name + "' has been learned");
  Session session(*this, simulator, nullptr, false);
  return session.perform_task(*task);
}

TaskLearningAgent::Session::Session(TaskLearningAgent& agent, Simulator& simulator, Dialogue* dialogue,
                                    bool learning)
    : agent_(agent), simulator_(simulator), dialogue_(dialogue), learning_(learning) {}

std::string TaskLearningAgent::Session::describe_object(ObjectId object) const {
  return world().universe->name(object) + " (" + world().universe->info(object).category + ")";
}

Result<std::string> TaskLearningAgent::Session::ask(QuestionKind kind, std::string text,
                                                    std::optional<ObjectId> object, std::optional<Goal> goal,
                                                    std::optional<Action> action) {
  APPRENTICE_CHECK(dialogue_ != nullptr);
  Question question;
  question.kind = kind;
  question.text = std::move(text);
  question.task = task_.name;
  question.subtask = subtask_verb_;
  question.object = object;
  question.goal = std::move(goal);
  question.action = action;
  return dialogue_->ask(question, world());
}

std::optional<ObjectId> TaskLearningAgent::Session::next_object(ObjectId place) {
  const Vocabulary& v = world().vocabulary;
  for (const Fact& f : world().state.facts()) {
    if ((f.predicate != v.on && f.predicate != v.in) || f.args[1] != place) continue;
    if (evaluated_.count(f.args[0])) continue;
    return f.args[0];
  }
  return std::nullopt;
}

Status TaskLearningAgent::Session::remember_task() {
  auto existing = std::find_if(agent_.knowledge_.tasks.begin(), agent_.knowledge_.tasks.end(),
                               [&](const TaskKnowledge& t) { return t.name == task_.name; });
  if (existing == agent_.knowledge_.tasks.end()) agent_.knowledge_.tasks.push_back(task_);
  else *existing = task_;
  if (agent_.store_) return agent_.store_->save_task(task_);
  return {};
}

Result<AgentReport> TaskLearningAgent::Session::learn_task() {
  auto name = ask(QuestionKind::kTaskName, "What task should I learn?");
  if (!name) return tl::unexpected(name.error());
  auto form = agent_.understanding_.parse(*name);
  if (!form || !std::holds_alternative<language::TaskName>(*form))
    return make_error(ErrorCode::kInvalidInput, "expected the name of a task, such as \"Tidy kitchen.\", not " + apprentice::quoted(*name));
  const auto& words = std::get<language::TaskName>(*form).words;
  task_.name = join(words, " ");
  task_verb_ = words.front();
  std::optional<Current> current;
  int confused = 0;
  for (;;) {
    auto reply = ask(QuestionKind::kTaskStep, language::say_next_goal_request(task_verb_));
    if (!reply) return tl::unexpected(reply.error());
    auto step = agent_.understanding_.parse(*reply);
    if (step && std::holds_alternative<language::Done>(*step)) break;
    if (step && std::holds_alternative<language::RepeatWhile>(*step)) {
      const auto& repeat = std::get<language::RepeatWhile>(*step);
      // The loop's place comes again in its subtask; here it must only exist.
      if (agent_.understanding_.place(world(), repeat.place, repeat.relation)) continue;
    } else if (step && std::holds_alternative<language::SubtaskCommand>(*step)) {
      const auto& command = std::get<language::SubtaskCommand>(*step);
      auto place = agent_.understanding_.place(world(), command.place, command.relation);
      if (place) {
        current = Current{command.verb, *place};
        task_.subtasks.push_back(LearnedSubtask{command.verb, std::string(language::to_string(command.relation)),
                                                world().universe->info(*place).category});
        if (auto s = remember_task(); !s) return tl::unexpected(s.error());
        if (auto s = run_first_iteration(*current); !s) return tl::unexpected(s.error());
        continue;
      }
    } else if (step && std::holds_alternative<language::Repeat>(*step) && current) {
      if (auto s = run_loop(*current); !s) return tl::unexpected(s.error());
      continue;
    }
    if (++confused > agent_.options_.max_retries)
      return make_error(ErrorCode::kInvalidInput, "the instructor's replies could not be understood: " + apprentice::quoted(*reply));
    dialogue_->say("I do not understand " + apprentice::quoted(*reply) + (step ? "" : ": " + step.error().message) + ".");
  }
  report_.task_finished = true;
  return report_;
}

Status TaskLearningAgent::Session::run_first_iteration(const Current& current) {
  subtask_verb_ = current.verb;
  auto object = next_object(current.place);
  if (!object) return {};
  ObjectReport report;
  if (auto s = handle_object(current, *object, report); !s) return s;
  // Learn where the subtask ends: with this object done, what is next? The
  // question is about the subtask, not the object.
  for (int attempt = 0; attempt <= agent_.options_.max_retries; ++attempt) {
    auto reply = ask(QuestionKind::kSubtaskStep, language::say_next_goal_request(current.verb));
    if (!reply) return tl::unexpected(reply.error());
    auto form = agent_.understanding_.parse(*reply);
    if (form && std::holds_alternative<language::Done>(*form)) return {};
    dialogue_->say("I expected to hear that " + current.verb + " is done.");
  }
  return {};
}

Status TaskLearningAgent::Session::run_loop(const Current& current) {
  subtask_verb_ = current.verb;
  while (auto object = next_object(current.place)) {
    ObjectReport report;
    if (auto s = handle_object(current, *object, report); !s) return s;
  }
  return {};
}

Status TaskLearningAgent::Session::handle_object(const Current& current, ObjectId object, ObjectReport& report) {
  evaluated_.insert(object);
  report.object = world().universe->name(object);
  report.subtask = current.verb;
  std::optional<Goal> goal;
  if (const GoalKnowledge* known = agent_.knowledge_.goals.find(goal_key(current, object))) {
    goal = instantiate_goal(world(), *known, object);
    if (goal) report.goal_source = "memory";
  }
  if (!goal) {
    if (!learning_) {
      report.note = "no goal known";
      report_.help_needed.push_back("a goal for " + describe_object(object) + " in " + current.verb);
      report_.objects.push_back(report);
      return {};
    }
    auto acquired = acquire_goal(current, object, report);
    if (!acquired) return tl::unexpected(acquired.error());
    goal = *acquired;
  }
  if (goal) {
    report.goal = format_goal(*world().domain, *world().universe, *goal);
    auto achieved = achieve(current, object, *goal, report);
    if (!achieved) return tl::unexpected(achieved.error());
    report.achieved = *achieved;
  }
  report_.objects.push_back(report);
  return {};
}

Result<AgentReport> TaskLearningAgent::Session::perform_task(const TaskKnowledge& task) {
  task_ = task;
  for (const LearnedSubtask& subtask : task.subtasks) {
    auto places = world().universe->with_category(subtask.place_category);
    if (places.size() != 1) {
      report_.help_needed.push_back("which " + subtask.place_category + " to " + subtask.verb +
                                    " (there are " + std::to_string(places.size()) + ")");
      continue;
    }
    Current current{subtask.verb, places.front()};
    if (auto s = run_loop(current); !s) return tl::unexpected(s.error());
  }
  report_.task_finished = true;
  return report_;
}

}  // namespace apprentice
